// The coupled system keeps its symbolic analysis while the coupled pairs stay the same, and a
// decoupled edge adds no coupling block.
#include <swslam/graph/coupled_system.h>

#include <gtest/gtest.h>

using namespace swslam::graph;

namespace
{
/** A chain 0-1-2-3 (free) plus a long edge 0-3 and an edge to a fixed pose (-1). */
std::vector<std::pair<int, int>> chainWithLongEdge() { return {{0, 1}, {1, 2}, {2, 3}, {0, 3}, {-1, 2}}; }
}  // namespace

TEST(CoupledSystem, AnalysisIsReusedWhileTheCoupledPairsStay)
{
  CoupledSystem sys;
  const auto pairs = chainWithLongEdge();
  sys.prepare(4, pairs, true);
  EXPECT_EQ(sys.analyses(), 1u);
  EXPECT_EQ(sys.decoupled(), 0u);
  for (size_t n = 0; n < pairs.size(); ++n) EXPECT_TRUE(sys.coupled(n));
  sys.prepare(4, pairs, true);  // the next stage: same edges
  sys.prepare(4, pairs, false);  // least squares on the same edges
  EXPECT_EQ(sys.analyses(), 1u);
}

TEST(CoupledSystem, WeakEdgesAreDecoupledOnlyWhenEnoughOfThem)
{
  CoupledSystem sys;
  const auto pairs = chainWithLongEdge();
  sys.prepare(4, pairs, true);
  const std::vector<char> weak = {0, 0, 0, 1, 1};  // the long edge; the fixed one has no coupling block anyway
  EXPECT_FALSE(sys.decouple(weak, 2));
  EXPECT_TRUE(sys.coupled(3));
  EXPECT_TRUE(sys.decouple(weak, 1));
  EXPECT_FALSE(sys.coupled(3));
  EXPECT_EQ(sys.decoupled(), 1u);
  EXPECT_EQ(sys.analyses(), 2u);
  EXPECT_FALSE(sys.decouple(weak, 1));  // nothing left to decouple
  // The stages keep the decoupling; least squares couples every edge again, with the first
  // pattern's pairs but a new analysis.
  sys.prepare(4, pairs, true);
  EXPECT_FALSE(sys.coupled(3));
  sys.prepare(4, pairs, false);
  EXPECT_TRUE(sys.coupled(3));
  EXPECT_EQ(sys.analyses(), 3u);
  // Other edges (a kept subset) start all coupled; without the long edge the pattern loses a
  // third of its pairs, more than the slack: a new analysis.
  const std::vector<std::pair<int, int>> kept(pairs.begin(), pairs.begin() + 3);
  sys.prepare(4, kept, true);
  EXPECT_EQ(sys.decoupled(), 0u);
  EXPECT_EQ(sys.analyses(), 4u);
}

TEST(CoupledSystem, PreparedDecoupledInOneAnalysis)
{
  CoupledSystem sys;
  const auto pairs = chainWithLongEdge();
  const std::vector<char> weak = {0, 0, 0, 1, 0};
  sys.prepareDecoupled(4, pairs, weak, 2);  // too few: all coupled
  EXPECT_TRUE(sys.coupled(3));
  EXPECT_EQ(sys.analyses(), 1u);
  sys.prepareDecoupled(4, pairs, weak, 1);
  EXPECT_FALSE(sys.coupled(3));
  EXPECT_TRUE(sys.coupled(0));
  EXPECT_EQ(sys.decoupled(), 1u);
  EXPECT_EQ(sys.analyses(), 2u);
}

TEST(CoupledSystem, APatternWithAFewPairsMoreIsReused)
{
  // A chain of 300 blocks and one long edge: least squares without the long edge reuses the
  // pattern (one pair in 300 more, within the slack), its solve unchanged by the structural
  // zeros; a subset with many pairs fewer gets its own analysis.
  std::vector<std::pair<int, int>> chain;
  for (int a = 0; a + 1 < 300; ++a) chain.emplace_back(a, a + 1);
  std::vector<std::pair<int, int>> with_long = chain;
  with_long.emplace_back(299, 0);  // reversed: the same pair as (0, 299)
  CoupledSystem sys;
  sys.prepare(300, with_long, false);
  sys.prepare(300, chain, false);
  EXPECT_EQ(sys.analyses(), 1u);
  NormalEquations& ne = sys.equations();
  NormalEquations own(300, chain);
  for (NormalEquations* e : {&ne, &own})
  {
    e->setZero();
    for (int a = 0; a < 300; ++a) e->addDiagonal(a, 3.0 * Eigen::Matrix3d::Identity());
    for (const auto& [a, b] : chain) e->addOffDiagonal(a, b, -Eigen::Matrix3d::Identity());
    e->gradient().setLinSpaced(900, -1.0, 1.0);
  }
  Eigen::VectorXd dx, dx_own;
  ASSERT_TRUE(ne.solveDamped(1e-3, dx));
  ASSERT_TRUE(own.solveDamped(1e-3, dx_own));
  EXPECT_LT((dx - dx_own).norm(), 1e-9 * dx_own.norm());
  sys.prepare(300, std::vector<std::pair<int, int>>(chain.begin(), chain.begin() + 100), false);
  EXPECT_EQ(sys.analyses(), 2u);
}

TEST(CoupledSystem, DecoupledEdgeAddsOnlyItsDiagonalBlocks)
{
  // The decoupled long edge leaves the chain's tridiagonal pattern: a solve with the chain's
  // blocks only matches a NormalEquations built from the chain alone.
  CoupledSystem sys;
  const auto pairs = chainWithLongEdge();
  sys.prepare(4, pairs, true);
  sys.decouple({0, 0, 0, 1, 0}, 1);
  NormalEquations& ne = sys.equations();
  NormalEquations chain(4, {{0, 1}, {1, 2}, {2, 3}});
  for (NormalEquations* e : {&ne, &chain})
  {
    e->setZero();
    for (int a = 0; a < 4; ++a) e->addDiagonal(a, (2.0 + a) * Eigen::Matrix3d::Identity());
    for (int a = 0; a < 3; ++a) e->addOffDiagonal(a, a + 1, -0.5 * Eigen::Matrix3d::Identity());
    e->gradient().setLinSpaced(12, -1.0, 1.0);
  }
  Eigen::VectorXd dx, dx_chain;
  ASSERT_TRUE(ne.solveDamped(0.0, dx));
  ASSERT_TRUE(chain.solveDamped(0.0, dx_chain));
  EXPECT_LT((dx - dx_chain).norm(), 1e-12);
  EXPECT_THROW(sys.prepare(2, pairs, false), std::invalid_argument);  // block 3 of 2
}

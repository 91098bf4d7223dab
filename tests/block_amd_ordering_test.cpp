// AMD on the 3x3 blocks of pose-graph normal equations: the block pattern against one built
// straight from the edge list, blocks kept whole, and a factor about as sparse as with AMD on
// the scalar pattern.
#include <swslam/block_amd_ordering.h>
#include <swslam/synthetic_graph.h>

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace
{
using Pairs = std::vector<std::pair<int, int>>;

/** Lower triangle of a block-sparse SPD matrix: dense 3x3 blocks on the diagonal and at
 * every pair (both triangles' blocks fold into the lower one). */
Eigen::SparseMatrix<double> lowerBlockMatrix(int blocks, const Pairs& pairs)
{
  std::vector<Eigen::Triplet<double>> t;
  // Diagonally dominant, so SPD.
  auto block = [&](int hi, int lo, double v, double diagonal) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        if (3 * hi + r >= 3 * lo + c) t.emplace_back(3 * hi + r, 3 * lo + c, r == c ? diagonal : v);
  };
  for (int a = 0; a < blocks; ++a) block(a, a, 1.0, 100.0);
  for (const auto& [a, b] : pairs) block(std::max(a, b), std::min(a, b), 0.1, 0.1);
  Eigen::SparseMatrix<double> m(3 * blocks, 3 * blocks);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

Pairs graphPairs(const swslam::PoseGraph& g)
{
  Pairs pairs;
  for (size_t k = 0; k < g.edgeCount(); ++k)
    pairs.emplace_back(static_cast<int>(g.edge(k).from), static_cast<int>(g.edge(k).to));
  return pairs;
}

Pairs gridWalkPairs(size_t nodes, size_t edges, size_t dense)
{
  swslam::SyntheticGraphOptions o;
  o.nodes = nodes;
  o.total_edges = edges;
  o.dense_neighbours = dense;
  o.seed = 5;
  return graphPairs(swslam::makeGridWalkGraph(o).graph);
}

template <typename Solver>
double factorNonZeros(const Eigen::SparseMatrix<double>& lower)
{
  Solver s;
  s.compute(lower);
  EXPECT_EQ(s.info(), Eigen::Success);
  const auto& L = s.matrixL();
  return static_cast<double>(Eigen::SparseMatrix<double>(L).nonZeros());
}
}  // namespace

TEST(BlockAmdOrdering, BlockPatternIsTheEdgeListsGraph)
{
  const int blocks = 60;
  const Pairs pairs = gridWalkPairs(blocks, 200, 2);
  const Eigen::SparseMatrix<double> lower = lowerBlockMatrix(blocks, pairs);
  // Eigen hands the ordering the full symmetric matrix.
  const Eigen::SparseMatrix<double> full = lower.selfadjointView<Eigen::Lower>();
  const Eigen::SparseMatrix<double> pattern = swslam::blockPattern(full, 3);
  std::set<std::pair<int, int>> expected, got;
  for (int a = 0; a < blocks; ++a) expected.emplace(a, a);
  for (const auto& [a, b] : pairs) expected.emplace(a, b), expected.emplace(b, a);
  for (int c = 0; c < pattern.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(pattern, c); it; ++it)
      got.emplace(static_cast<int>(it.row()), c);
  EXPECT_EQ(got, expected);
  // One triangle gives the same (symmetric) pattern.
  const Eigen::SparseMatrix<double> from_lower = swslam::blockPattern(lower, 3);
  EXPECT_EQ(from_lower.nonZeros(), pattern.nonZeros());
}

TEST(BlockAmdOrdering, EqualsAmdOnTheBlockGraphWithBlocksKeptWhole)
{
  const int blocks = 80;
  const Pairs pairs = gridWalkPairs(blocks, 260, 1);
  const Eigen::SparseMatrix<double> full =
      Eigen::SparseMatrix<double>(lowerBlockMatrix(blocks, pairs).selfadjointView<Eigen::Lower>());
  const swslam::SparsePermutation perm = swslam::blockAmdOrdering(full, 3);

  // The slow way: the block graph straight from the pairs, Eigen's AMD, expanded by hand.
  Eigen::SparseMatrix<double> block_graph(blocks, blocks);
  std::vector<Eigen::Triplet<double>> t;
  for (int a = 0; a < blocks; ++a) t.emplace_back(a, a, 1.0);
  for (const auto& [a, b] : pairs) t.emplace_back(a, b, 1.0), t.emplace_back(b, a, 1.0);
  block_graph.setFromTriplets(t.begin(), t.end());
  swslam::SparsePermutation block_perm;
  Eigen::AMDOrdering<int> amd;
  amd(block_graph, block_perm);

  ASSERT_EQ(perm.size(), 3 * blocks);
  std::set<int> targets;
  for (int b = 0; b < blocks; ++b)
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(perm.indices()[3 * b + k], 3 * block_perm.indices()[b] + k);
      targets.insert(perm.indices()[3 * b + k]);
    }
  EXPECT_EQ(targets.size(), static_cast<size_t>(3 * blocks));  // a permutation
}

TEST(BlockAmdOrdering, FactorAboutAsSparseAsWithScalarAmd)
{
  // A valley-like graph: a long walk, each node linked to 4 predecessors, with loops.
  const int blocks = 600;
  const Eigen::SparseMatrix<double> lower = lowerBlockMatrix(blocks, gridWalkPairs(blocks, 3000, 4));
  using ScalarAmd = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower>;
  using BlockAmd = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower,
                                         swslam::BlockAmdOrdering<3>>;
  const double scalar = factorNonZeros<ScalarAmd>(lower);
  const double block = factorNonZeros<BlockAmd>(lower);
  EXPECT_LT(block, 1.25 * scalar) << "block " << block << ", scalar " << scalar;
  // And it solves the same system.
  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(3 * blocks, -1.0, 1.0);
  BlockAmd s;
  s.compute(lower);
  const Eigen::VectorXd x = s.solve(b);
  const Eigen::SparseMatrix<double> full = lower.selfadjointView<Eigen::Lower>();
  EXPECT_LT((full * x - b).norm(), 1e-10 * b.norm());
}

TEST(BlockAmdOrdering, MatrixNotMadeOfBlocksIsAnError)
{
  Eigen::SparseMatrix<double> m(10, 10);
  m.setIdentity();
  EXPECT_THROW(swslam::blockPattern(m, 3), std::invalid_argument);
  EXPECT_THROW(swslam::blockPattern(Eigen::SparseMatrix<double>(6, 9), 3), std::invalid_argument);
  EXPECT_THROW(swslam::blockPattern(m, 0), std::invalid_argument);
  EXPECT_NO_THROW(swslam::blockPattern(m, 5));
}

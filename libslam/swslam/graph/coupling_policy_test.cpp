// Each coupling policy decouples what it says: nothing (All), the edges weak at the start and
// after each step (DecoupleWeak, from the last solve's or afresh), and under Exact only where
// every edge coupled would make the factor dense, then at the preconditioner's weight.
#include <swslam/graph/coupling_policy.h>

#include <gtest/gtest.h>

using namespace swslam::graph;

namespace
{
/** A chain of n free blocks and, every 10th block, a long edge back to block 0. */
std::vector<std::pair<int, int>> chainWithLongEdges(int n)
{
  std::vector<std::pair<int, int>> pairs;
  for (int b = 1; b < n; ++b) pairs.emplace_back(b - 1, b);
  for (int b = 10; b < n; b += 10) pairs.emplace_back(0, b);
  return pairs;
}

/** Every pair of n blocks: a dense factor. */
std::vector<std::pair<int, int>> clique(int n)
{
  std::vector<std::pair<int, int>> pairs;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) pairs.emplace_back(a, b);
  return pairs;
}

/** Flags the pairs with the lower block 0 (the long edges) as weak, and records the weight
 * asked for. */
struct LongEdgesWeak
{
  explicit LongEdgesWeak(const std::vector<std::pair<int, int>>& pairs) : pairs(pairs) {}
  std::vector<char> operator()(double weight)
  {
    asked.push_back(weight);
    std::vector<char> weak(pairs.size());
    for (size_t n = 0; n < pairs.size(); ++n) weak[n] = pairs[n].first == 0 && pairs[n].second > 1;
    return weak;
  }
  std::vector<std::pair<int, int>> pairs;
  std::vector<double> asked;
};

size_t decoupledLongEdges(const CoupledSystem& sys, const std::vector<std::pair<int, int>>& pairs)
{
  size_t count = 0;
  for (size_t n = 0; n < pairs.size(); ++n) count += !sys.coupled(n);
  return count;
}
}  // namespace

TEST(CouplingPolicy, AllCouplesEveryEdge)
{
  const auto pairs = chainWithLongEdges(200);
  LongEdgesWeak weak(pairs);
  CoupledSystem sys;
  prepareCoupling(sys, Coupling::All, 200, pairs, std::ref(weak));
  decoupleAfterStep(sys, Coupling::All, pairs.size(), std::ref(weak));
  EXPECT_EQ(decoupledLongEdges(sys, pairs), 0u);
  EXPECT_TRUE(weak.asked.empty());
}

TEST(CouplingPolicy, DecoupleWeakTakesTheWeakEdgesOutWhenEnoughOfThem)
{
  const auto pairs = chainWithLongEdges(200);  // 19 long edges of 218: above 1 %
  for (const Coupling c : {Coupling::DecoupleWeak, Coupling::DecoupleWeakAfresh})
  {
    LongEdgesWeak weak(pairs);
    CoupledSystem sys;
    prepareCoupling(sys, c, 200, pairs, std::ref(weak));
    EXPECT_EQ(decoupledLongEdges(sys, pairs), 19u);
    ASSERT_FALSE(weak.asked.empty());
    EXPECT_EQ(weak.asked.back(), kDecoupledWeight);
  }
  // One weak edge in 200 (fewer than 1 % of them, 2): nothing decoupled.
  std::vector<std::pair<int, int>> one = chainWithLongEdges(200);
  one.resize(200);  // the chain and the first long edge
  LongEdgesWeak weak(one);
  CoupledSystem sys;
  prepareCoupling(sys, Coupling::DecoupleWeakAfresh, 200, one, std::ref(weak));
  EXPECT_EQ(minDecoupled(one.size()), 2u);
  EXPECT_EQ(decoupledLongEdges(sys, one), 0u);
  EXPECT_EQ(minDecoupled(1000), 10u);
}

TEST(CouplingPolicy, DecoupleWeakKeepsTheLastSolvesDecouplingAndAfreshDoesNot)
{
  const auto pairs = chainWithLongEdges(200);
  LongEdgesWeak weak(pairs);
  CoupledSystem sys;
  prepareCoupling(sys, Coupling::DecoupleWeakAfresh, 200, pairs, std::ref(weak));
  ASSERT_EQ(decoupledLongEdges(sys, pairs), 19u);
  // Nothing weak any more: DecoupleWeak keeps the 19 out, DecoupleWeakAfresh couples them again.
  auto none = [&](double) { return std::vector<char>(pairs.size(), 0); };
  prepareCoupling(sys, Coupling::DecoupleWeak, 200, pairs, none);
  EXPECT_EQ(decoupledLongEdges(sys, pairs), 19u);
  prepareCoupling(sys, Coupling::DecoupleWeakAfresh, 200, pairs, none);
  EXPECT_EQ(decoupledLongEdges(sys, pairs), 0u);
  // And after a step, the edges weak then go out.
  decoupleAfterStep(sys, Coupling::DecoupleWeak, pairs.size(), std::ref(weak));
  EXPECT_EQ(decoupledLongEdges(sys, pairs), 19u);
}

TEST(CouplingPolicy, ExactDecouplesOnlyWhereTheFactorWouldBeDense)
{
  {
    const auto pairs = chainWithLongEdges(200);  // sparse: every edge coupled, weak or not
    LongEdgesWeak weak(pairs);
    CoupledSystem sys;
    prepareCoupling(sys, Coupling::Exact, 200, pairs, std::ref(weak));
    decoupleAfterStep(sys, Coupling::Exact, pairs.size(), std::ref(weak));
    EXPECT_EQ(decoupledLongEdges(sys, pairs), 0u);
  }
  const auto pairs = clique(80);
  ASSERT_GT(NormalEquations::fillPerColumnOf(80, pairs), kDenseFillPerColumn);
  LongEdgesWeak weak(pairs);
  CoupledSystem sys;
  prepareCoupling(sys, Coupling::Exact, 80, pairs, std::ref(weak));
  EXPECT_EQ(decoupledLongEdges(sys, pairs), 78u);  // block 0 to blocks 2..79
  ASSERT_EQ(weak.asked.size(), 1u);
  EXPECT_EQ(weak.asked[0], kPreconditionerWeight);
  // The whole solve keeps that pattern.
  decoupleAfterStep(sys, Coupling::Exact, pairs.size(), std::ref(weak));
  EXPECT_EQ(weak.asked.size(), 1u);
}

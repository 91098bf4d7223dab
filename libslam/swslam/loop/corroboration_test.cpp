// Loop corroboration: a lone loop waits, a second one that agrees through the graph releases
// both, a disagreeing one stays out, and a loop whose partner comes too late never enters.
#include <swslam/loop/corroboration.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam;
using namespace swslam::loop;
using mrpt::poses::CPose2D;

namespace
{
// A loop around a 20 m x 10 m rectangle, one node per metre: node i and node i + 60 are
// 0.2 m apart (the second lap runs 0.2 m to the side of the first).
CPose2D nodePose(size_t i)
{
  const size_t lap = i / 60, k = i % 60;
  const double side = 0.2 * static_cast<double>(lap);
  if (k < 20) return {static_cast<double>(k), side, 0};
  if (k < 30) return {20 - side, static_cast<double>(k - 20), M_PI / 2};
  if (k < 50) return {static_cast<double>(50 - k), 10 - side, M_PI};
  return {side, static_cast<double>(60 - k), -M_PI / 2};
}

graph::Constraint loopEdge(size_t from, size_t to, const CPose2D& error = CPose2D())
{
  graph::Constraint e;
  e.from = from;
  e.to = to;
  e.z = (nodePose(to) - nodePose(from)) + error;
  e.information = Eigen::Vector3d(1e4, 1e4, 1e5).asDiagonal();
  e.kind = graph::EdgeKind::Loop;
  return e;
}

std::vector<graph::Constraint> add(LoopCorroboration& c, size_t newest, const std::vector<graph::Constraint>& v)
{
  return c.add(newest, v, nodePose, [](size_t i) { return static_cast<double>(i); });
}
}  // namespace

TEST(LoopCorroboration, ALoneLoopWaitsAndAnAgreeingOneReleasesBoth)
{
  LoopClosureParams p;
  p.consistency_window = 10;
  LoopCorroboration c(p);
  EXPECT_TRUE(add(c, 62, {loopEdge(2, 62)}).empty());
  EXPECT_EQ(c.waiting(), 1u);
  const auto out = add(c, 64, {loopEdge(4, 64)});
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].from, 2u);  // the waiting loop first, then the new one
  EXPECT_EQ(out[1].from, 4u);
  // A third agreeing loop comes out alone: the others are in the graph already.
  const auto third = add(c, 66, {loopEdge(6, 66)});
  ASSERT_EQ(third.size(), 1u);
  EXPECT_EQ(third[0].to, 66u);
}

TEST(LoopCorroboration, AWrongLoopIsNotReleasedByAGoodOne)
{
  LoopClosureParams p;
  p.consistency_window = 10;
  LoopCorroboration c(p);
  // 1 m off along the path: a self-similar place matched one metre early.
  EXPECT_TRUE(add(c, 63, {loopEdge(3, 63, CPose2D(1.0, 0, 0))}).empty());
  EXPECT_TRUE(add(c, 65, {loopEdge(5, 65)}).empty());
  // Two good loops later, the wrong one is still out; the good ones agree.
  const auto out = add(c, 67, {loopEdge(7, 67)});
  ASSERT_EQ(out.size(), 2u);
  for (const auto& e : out) EXPECT_NE(e.from, 3u);
  // Loops verified at the same node corroborate each other too.
  LoopCorroboration d(p);
  EXPECT_EQ(add(d, 70, {loopEdge(10, 70), loopEdge(11, 70)}).size(), 2u);
}

TEST(LoopCorroboration, ALoopWhosePartnerComesTooLateStopsWaiting)
{
  LoopClosureParams p;
  p.consistency_window = 5;
  LoopCorroboration c(p);
  EXPECT_TRUE(add(c, 62, {loopEdge(2, 62)}).empty());
  // Node 68 is 6 > 5 nodes after 62: the first loop has expired and the new one waits alone.
  EXPECT_TRUE(add(c, 68, {loopEdge(4, 68)}).empty());
  EXPECT_EQ(c.waiting(), 1u);
}

TEST(LoopCorroboration, AWindowOfZeroPassesEveryLoop)
{
  LoopClosureParams p;
  p.consistency_window = 0;
  LoopCorroboration c(p);
  EXPECT_EQ(add(c, 63, {loopEdge(3, 63, CPose2D(1.0, 0, 0))}).size(), 1u);
  EXPECT_EQ(c.waiting(), 0u);
}

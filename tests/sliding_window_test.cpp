// The sliding window: which nodes are free, which are held fixed, which edges constrain it
// (compared with a brute-force scan of all edges), and that only the window moves.
#include <swslam/sliding_window.h>
#include <swslam/synthetic_graph.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace
{
swslam::SyntheticGraph grid(size_t nodes, unsigned seed)
{
  swslam::SyntheticGraphOptions o;
  o.nodes = nodes;
  o.total_edges = 3 * nodes;
  o.seed = seed;
  return swslam::makeGridWalkGraph(o);
}
}  // namespace

TEST(SlidingWindow, WindowHoldsTheNewestNodesAndEveryEdgeTouchingThem)
{
  for (size_t nodes : {100, 2000})
  {
    const auto s = grid(nodes, 5);
    const auto sub = swslam::windowSubproblem(s.graph, 30, {});
    const auto window = s.graph.newestNodes(30);
    const std::set<size_t> in_window(window.begin(), window.end());
    // Brute force: every edge with at least one end in the window.
    std::vector<size_t> expected;
    std::set<size_t> expected_fixed;
    for (size_t k = 0; k < s.graph.edgeCount(); ++k)
    {
      const auto& e = s.graph.edge(k);
      if (!in_window.count(e.from) && !in_window.count(e.to)) continue;
      expected.push_back(k);
      for (auto id : {e.from, e.to})
        if (!in_window.count(id)) expected_fixed.insert(id);
    }
    std::vector<size_t> got = sub.edge_indices;
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, expected) << nodes << " nodes";
    ASSERT_FALSE(expected_fixed.empty());
    std::set<size_t> free, fixed;
    for (size_t n = 0; n < sub.node_ids.size(); ++n)
      (sub.problem.fixed[n] ? fixed : free).insert(sub.node_ids[n]);
    EXPECT_EQ(free, in_window);
    EXPECT_EQ(fixed, expected_fixed);
  }
}

TEST(SlidingWindow, OnlyTheWindowMovesAndItsErrorDrops)
{
  auto s = grid(300, 8);
  const swslam::PoseGraph before = s.graph;
  swslam::GraphOptimizerParams params;
  params.window_size = 30;
  const auto rep = swslam::optimizeWindow(s.graph, params);
  ASSERT_NE(rep.status, swslam::OptimizationStatus::Diverged) << rep.message;
  EXPECT_EQ(rep.free_nodes, 30u);
  EXPECT_LT(rep.final_chi2, rep.initial_chi2);
  EXPECT_LE(rep.final_cost, rep.initial_cost);
  const auto window = s.graph.newestNodes(30);
  size_t moved = 0;
  for (const auto id : s.graph.nodeIds())
  {
    const bool same = s.graph.pose(id) == before.pose(id);
    if (std::find(window.begin(), window.end(), id) == window.end()) EXPECT_TRUE(same) << id;
    else moved += !same;
  }
  EXPECT_EQ(moved, 30u);
}

TEST(SlidingWindow, AWindowOverTheWholeGraphKeepsTheRootFixed)
{
  auto s = grid(20, 2);
  const auto sub = swslam::windowSubproblem(s.graph, 50, {});
  EXPECT_EQ(sub.node_ids.size(), 20u);
  EXPECT_EQ(std::count(sub.problem.fixed.begin(), sub.problem.fixed.end(), 1), 1);
  EXPECT_EQ(sub.node_ids[std::find(sub.problem.fixed.begin(), sub.problem.fixed.end(), 1) -
                         sub.problem.fixed.begin()],
            s.graph.root());
  const auto root_pose = s.graph.pose(s.graph.root());
  swslam::GraphOptimizerParams params;
  params.window_size = 50;
  swslam::optimizeWindow(s.graph, params);
  EXPECT_EQ(s.graph.pose(s.graph.root()), root_pose);
}

TEST(SlidingWindow, EmptyGraphOrWindowIsAnError)
{
  swslam::PoseGraph empty;
  EXPECT_THROW(swslam::windowSubproblem(empty, 30, {}), std::invalid_argument);
  EXPECT_THROW(swslam::fullSubproblem(empty, {}), std::invalid_argument);
  auto s = grid(10, 1);
  EXPECT_THROW(swslam::windowSubproblem(s.graph, 0, {}), std::invalid_argument);
  swslam::PoseGraph single;
  single.addNode(0, {});
  EXPECT_EQ(swslam::optimizeWindow(single, {}).status, swslam::OptimizationStatus::NothingToOptimize);
}

TEST(SlidingWindow, RobustifiedEdgesFollowTheirKind)
{
  auto s = grid(100, 3);
  swslam::GraphOptimizerParams params;
  params.robust_loop = false;
  const auto sub = swslam::fullSubproblem(s.graph, params);
  for (size_t k = 0; k < sub.edge_indices.size(); ++k)
  {
    const auto kind = s.graph.edge(sub.edge_indices[k]).kind;
    EXPECT_EQ(sub.problem.edges[k].robust, kind == swslam::EdgeKind::Consecutive);
  }
}

TEST(SlidingWindow, DivergenceIsReportedAndLeavesTheGraphIntact)
{
  // An information of 1e308 on a 10 m error overflows the cost to infinity.
  swslam::PoseGraph g;
  for (int k = 0; k < 3; ++k) g.addNode(k, mrpt::poses::CPose2D(k, 0, 0));
  mrpt::poses::CPosePDFGaussianInf z;
  z.mean = mrpt::poses::CPose2D(1, 0, 0);
  z.cov_inv.setIdentity();
  g.addEdge(0, 1, z, swslam::EdgeKind::Consecutive);
  z.mean = mrpt::poses::CPose2D(11, 0, 0);
  z.cov_inv *= 1e308;
  g.addEdge(1, 2, z, swslam::EdgeKind::Consecutive);
  const swslam::PoseGraph before = g;
  for (bool window : {false, true})
  {
    const auto rep = window ? swslam::optimizeWindow(g, {}) : swslam::optimizeFull(g, {});
    EXPECT_EQ(rep.status, swslam::OptimizationStatus::Diverged);
    EXPECT_NE(rep.message.find("not finite"), std::string::npos);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(g.pose(k), before.pose(k));
  }
}

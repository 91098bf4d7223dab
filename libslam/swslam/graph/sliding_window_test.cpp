// The sliding window: which nodes are free, which are held fixed, which edges constrain it
// (compared with a brute-force scan of all edges), and that only the window moves. The whole
// graph (optimizeFull) against known truth: MRPT's circle graph, and synthetic grid walks with
// 10-30 % wrong loop edges where only a robust kernel keeps the map right.
#include <swslam/graph/io.h>
#include <swslam/graph/sliding_window.h>
#include <swslam/graph/synthetic.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace
{
swslam::graph::SyntheticGraph grid(size_t nodes, unsigned seed)
{
  swslam::graph::SyntheticGraphOptions o;
  o.nodes = nodes;
  o.total_edges = 3 * nodes;
  o.seed = seed;
  return swslam::graph::makeGridWalkGraph(o);
}
}  // namespace

TEST(SlidingWindow, WindowHoldsTheNewestNodesAndEveryEdgeTouchingThem)
{
  for (size_t nodes : {100, 2000})
  {
    const auto s = grid(nodes, 5);
    const auto sub = swslam::graph::windowSubproblem(s.graph, 30, {});
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
  const swslam::graph::PoseGraph before = s.graph;
  swslam::graph::GraphOptimizerParams params;
  params.window_size = 30;
  const auto rep = swslam::graph::optimizeWindow(s.graph, params);
  ASSERT_NE(rep.status, swslam::graph::OptimizationStatus::Diverged) << rep.message;
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
  const auto sub = swslam::graph::windowSubproblem(s.graph, 50, {});
  EXPECT_EQ(sub.node_ids.size(), 20u);
  EXPECT_EQ(std::count(sub.problem.fixed.begin(), sub.problem.fixed.end(), 1), 1);
  EXPECT_EQ(sub.node_ids[std::find(sub.problem.fixed.begin(), sub.problem.fixed.end(), 1) -
                         sub.problem.fixed.begin()],
            s.graph.root());
  const auto root_pose = s.graph.pose(s.graph.root());
  swslam::graph::GraphOptimizerParams params;
  params.window_size = 50;
  swslam::graph::optimizeWindow(s.graph, params);
  EXPECT_EQ(s.graph.pose(s.graph.root()), root_pose);
}

TEST(SlidingWindow, EmptyGraphOrWindowIsAnError)
{
  swslam::graph::PoseGraph empty;
  EXPECT_THROW(swslam::graph::windowSubproblem(empty, 30, {}), std::invalid_argument);
  EXPECT_THROW(swslam::graph::fullSubproblem(empty, {}), std::invalid_argument);
  auto s = grid(10, 1);
  EXPECT_THROW(swslam::graph::windowSubproblem(s.graph, 0, {}), std::invalid_argument);
  swslam::graph::PoseGraph single;
  single.addNode(0, {});
  EXPECT_EQ(swslam::graph::optimizeWindow(single, {}).status, swslam::graph::OptimizationStatus::NothingToOptimize);
}

TEST(SlidingWindow, RobustifiedEdgesFollowTheirKind)
{
  auto s = grid(100, 3);
  swslam::graph::GraphOptimizerParams params;
  params.robust_loop = false;
  const auto sub = swslam::graph::fullSubproblem(s.graph, params);
  for (size_t k = 0; k < sub.edge_indices.size(); ++k)
  {
    const auto kind = s.graph.edge(sub.edge_indices[k]).kind;
    EXPECT_EQ(sub.problem.edges[k].robust, kind == swslam::graph::EdgeKind::Consecutive);
  }
}

TEST(SlidingWindow, DivergenceIsReportedAndLeavesTheGraphIntact)
{
  // An information of 1e308 on a 10 m error overflows the cost to infinity.
  swslam::graph::PoseGraph g;
  for (int k = 0; k < 3; ++k) g.addNode(k, mrpt::poses::CPose2D(k, 0, 0));
  mrpt::poses::CPosePDFGaussianInf z;
  z.mean = mrpt::poses::CPose2D(1, 0, 0);
  z.cov_inv.setIdentity();
  g.addEdge(0, 1, z, swslam::graph::EdgeKind::Consecutive);
  z.mean = mrpt::poses::CPose2D(11, 0, 0);
  z.cov_inv *= 1e308;
  g.addEdge(1, 2, z, swslam::graph::EdgeKind::Consecutive);
  const swslam::graph::PoseGraph before = g;
  for (bool window : {false, true})
  {
    const auto rep = window ? swslam::graph::optimizeWindow(g, {}) : swslam::graph::optimizeFull(g, {});
    EXPECT_EQ(rep.status, swslam::graph::OptimizationStatus::Diverged);
    EXPECT_NE(rep.message.find("not finite"), std::string::npos);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(g.pose(k), before.pose(k));
  }
}

TEST(OptimizeFull, MrptCircleGraphConvergesToItsGroundTruth)
{
  const std::string base = std::string(SWSLAM_MRPT_DATASETS) + "/graph_2d_circle_50nodes";
  const auto truth = swslam::graph::truthFromGraph(swslam::graph::loadGraph(base + "_groundtruth.graph"));
  for (double alpha : {2.0, 0.0})
  {
    auto graph = swslam::graph::loadGraph(base + ".graph");
    const auto initial = swslam::graph::compareToTruth(graph, truth);
    swslam::graph::GraphOptimizerParams params;
    params.kernel_alpha = alpha;
    const auto rep = swslam::graph::optimizeFull(graph, params);
    EXPECT_EQ(rep.status, swslam::graph::OptimizationStatus::Converged) << rep.message;
    const auto err = swslam::graph::compareToTruth(graph, truth);
    EXPECT_GT(initial.rmse_xy, 0.3);
    EXPECT_LT(err.rmse_xy, 0.03) << "alpha " << alpha;
    EXPECT_LT(err.max_xy, 0.06);
    EXPECT_LT(err.rmse_theta, 0.01);
    EXPECT_LT(rep.final_chi2, 0.01);
  }
}

TEST(OptimizeFull, RobustKernelRejectsWrongLoopsThatRuinL2)
{
  // Bounds: the outlier-free L2 solution of this graph is within rmse ~0.07 m of truth.
  // A robust kernel must stay within 0.15 m rmse (0.5 m worst node) with 10-30 % wrong
  // loops; plain L2 on the same graph and settings must be off by more than 1 m rmse.
  for (double wrong : {0.0, 0.1, 0.2, 0.3})
  {
    swslam::graph::SyntheticGraphOptions o;
    o.nodes = 400;
    o.total_edges = 1200;
    o.wrong_loop_fraction = wrong;
    o.seed = 21;
    const auto s = swslam::graph::makeGridWalkGraph(o);
    ASSERT_GT(s.good_loops, 100u);
    for (double alpha : {2.0, 0.0, -2.0})
    {
      auto graph = s.graph;
      swslam::graph::GraphOptimizerParams params;
      params.kernel_alpha = alpha;
      const auto rep = swslam::graph::optimizeFull(graph, params);
      ASSERT_NE(rep.status, swslam::graph::OptimizationStatus::Diverged) << rep.message;
      const auto err = swslam::graph::compareToTruth(graph, s.truth);
      if (alpha < 2.0 && wrong > 0.0)  // outliers are down-weighted: the Fig. 7 signal stays small
        EXPECT_LT(rep.active_sq_residuals, 0.5 * rep.final_chi2);
      if (alpha < 2.0 || wrong == 0.0)
      {
        EXPECT_LT(err.rmse_xy, 0.15) << "wrong " << wrong << " alpha " << alpha;
        EXPECT_LT(err.max_xy, 0.5) << "wrong " << wrong << " alpha " << alpha;
      }
      else
      {
        EXPECT_GT(err.rmse_xy, 1.0) << "wrong " << wrong << " alpha " << alpha;
      }
    }
  }
}

TEST(OptimizeFull, TruthNeedsNodeIdsFromZero)
{
  swslam::graph::PoseGraph g;
  g.addNode(0, {});
  g.addNode(2, {});
  EXPECT_THROW(swslam::graph::truthFromGraph(g), std::invalid_argument);
  EXPECT_THROW(swslam::graph::compareToTruth(g, {swslam::geometry::Pose2::Zero()}), std::invalid_argument);
}

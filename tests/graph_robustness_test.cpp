// Whole-graph optimization against known truth: MRPT's circle graph, and synthetic grid
// walks with 10-30 % wrong loop edges where only a robust kernel keeps the map right.
#include <swslam/graph_io.h>
#include <swslam/sliding_window.h>
#include <swslam/synthetic_graph.h>

#include <gtest/gtest.h>

TEST(GraphRobustness, MrptCircleGraphConvergesToItsGroundTruth)
{
  const std::string base = std::string(SWSLAM_MRPT_DATASETS) + "/graph_2d_circle_50nodes";
  const auto truth = swslam::truthFromGraph(swslam::loadGraph(base + "_groundtruth.graph"));
  for (double alpha : {2.0, 0.0})
  {
    auto graph = swslam::loadGraph(base + ".graph");
    const auto initial = swslam::compareToTruth(graph, truth);
    swslam::GraphOptimizerParams params;
    params.kernel_alpha = alpha;
    const auto rep = swslam::optimizeFull(graph, params);
    EXPECT_EQ(rep.status, swslam::OptimizationStatus::Converged) << rep.message;
    const auto err = swslam::compareToTruth(graph, truth);
    EXPECT_GT(initial.rmse_xy, 0.3);
    EXPECT_LT(err.rmse_xy, 0.03) << "alpha " << alpha;
    EXPECT_LT(err.max_xy, 0.06);
    EXPECT_LT(err.rmse_theta, 0.01);
    EXPECT_LT(rep.final_chi2, 0.01);
  }
}

TEST(GraphRobustness, RobustKernelRejectsWrongLoopsThatRuinL2)
{
  // Bounds: the outlier-free L2 solution of this graph is within rmse ~0.07 m of truth.
  // A robust kernel must stay within 0.15 m rmse (0.5 m worst node) with 10-30 % wrong
  // loops; plain L2 on the same graph and settings must be off by more than 1 m rmse.
  for (double wrong : {0.0, 0.1, 0.2, 0.3})
  {
    swslam::SyntheticGraphOptions o;
    o.nodes = 400;
    o.total_edges = 1200;
    o.wrong_loop_fraction = wrong;
    o.seed = 21;
    const auto s = swslam::makeGridWalkGraph(o);
    ASSERT_GT(s.good_loops, 100u);
    for (double alpha : {2.0, 0.0, -2.0})
    {
      auto graph = s.graph;
      swslam::GraphOptimizerParams params;
      params.kernel_alpha = alpha;
      const auto rep = swslam::optimizeFull(graph, params);
      ASSERT_NE(rep.status, swslam::OptimizationStatus::Diverged) << rep.message;
      const auto err = swslam::compareToTruth(graph, s.truth);
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

TEST(GraphRobustness, TruthNeedsNodeIdsFromZero)
{
  swslam::PoseGraph g;
  g.addNode(0, {});
  g.addNode(2, {});
  EXPECT_THROW(swslam::truthFromGraph(g), std::invalid_argument);
  EXPECT_THROW(swslam::compareToTruth(g, {swslam::Pose2::Zero()}), std::invalid_argument);
}

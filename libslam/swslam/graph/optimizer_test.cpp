// Levenberg-Marquardt + IRLS on small pose-graph problems, and its parameters.
#include <swslam/common/param_table.h>
#include <swslam/graph/optimizer.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <cmath>

using swslam::graph::GraphProblem;
using swslam::graph::OptimizationStatus;
using swslam::geometry::Pose2;

namespace
{
/** A square loop of 4 nodes with exact measurements and a perturbed initial estimate. */
GraphProblem squareLoop(bool robust)
{
  const std::vector<swslam::geometry::Pose2> truth{{0, 0, 0}, {2, 0, M_PI / 2}, {2, 2, M_PI}, {0, 2, -M_PI / 2}};
  GraphProblem p;
  p.poses = {{0, 0, 0}, {2.3, 0.2, 1.4}, {1.7, 2.4, 3.0}, {0.1, 1.6, -1.2}};
  p.fixed = {1, 0, 0, 0};
  for (int k = 0; k < 4; ++k)
  {
    GraphProblem::Edge e;
    e.i = k, e.j = (k + 1) % 4;
    e.z = swslam::geometry::relativePose(truth[e.i], truth[e.j]);
    e.information = Eigen::Vector3d(100, 100, 400).asDiagonal();
    e.robust = robust;
    p.edges.push_back(e);
  }
  return p;
}
}  // namespace

TEST(GraphOptimizer, ConvergesToTheExactSolutionOfAConsistentLoop)
{
  for (bool robust : {false, true})
  {
    GraphProblem p = squareLoop(robust);
    const auto rep = swslam::graph::optimizeGraphProblem(p, swslam::graph::GraphOptimizerParams{});
    EXPECT_EQ(rep.status, OptimizationStatus::Converged) << rep.message;
    EXPECT_GT(rep.initial_chi2, 100.0);
    EXPECT_LT(rep.final_chi2, 1e-12);
    EXPECT_LT((p.poses[2] - swslam::geometry::Pose2(2, 2, M_PI)).head<2>().norm(), 1e-6);
    EXPECT_NEAR(std::abs(p.poses[2].z()), M_PI, 1e-6);  // across the seam
    EXPECT_EQ(p.poses[0], swslam::geometry::Pose2(0, 0, 0));               // the fixed gauge did not move
    EXPECT_EQ(rep.free_nodes, 3u);
    EXPECT_NEAR(rep.active_sq_residuals, rep.final_chi2, 1e-9);
  }
}

TEST(GraphOptimizer, WithoutFixedPoseTheFirstIsTheGauge)
{
  GraphProblem p = squareLoop(false);
  p.fixed = {0, 0, 0, 0};
  const auto rep = swslam::graph::optimizeGraphProblem(p, swslam::graph::GraphOptimizerParams{});
  EXPECT_EQ(rep.status, OptimizationStatus::Converged);
  EXPECT_EQ(rep.fixed_nodes, 1u);
  EXPECT_EQ(p.poses[0], swslam::geometry::Pose2(0, 0, 0));
}

TEST(GraphOptimizer, EachConnectedComponentIsHeldAtItsFirstPose)
{
  // Two square loops that share no edge, and a pose joined to nothing: the second loop has no
  // fixed pose, so its first pose is its gauge; the lone pose stays where it is.
  GraphProblem p = squareLoop(false);
  const GraphProblem second = squareLoop(false);
  for (const Pose2& pose : second.poses) p.poses.push_back(pose + Pose2(10, 0, 0));
  p.poses.push_back(Pose2(-5, -5, 1));
  p.fixed.resize(p.poses.size(), 0);
  for (GraphProblem::Edge e : second.edges)
  {
    e.i += 4, e.j += 4;
    p.edges.push_back(e);
  }
  const std::vector<Pose2> before = p.poses;
  const auto rep = swslam::graph::optimizeGraphProblem(p, swslam::graph::GraphOptimizerParams{});
  EXPECT_EQ(rep.status, OptimizationStatus::Converged) << rep.message;
  EXPECT_EQ(rep.components, 3u);
  EXPECT_EQ(rep.fixed_nodes, 3u);
  EXPECT_EQ(p.poses[0], before[0]);
  EXPECT_EQ(p.poses[4], before[4]);
  EXPECT_EQ(p.poses[8], before[8]);
  EXPECT_LT(rep.final_chi2, 1e-12);
  // The second loop is solved relative to its own gauge: its third pose is (2, 2, pi) from it.
  const Pose2 rel = swslam::geometry::relativePose(p.poses[4], p.poses[6]);
  EXPECT_LT((rel - Pose2(2, 2, M_PI)).head<2>().norm(), 1e-6);
}

TEST(GraphOptimizer, NonFinitePoseIsReportedAndLeavesTheEstimateIntact)
{
  GraphProblem p = squareLoop(false);
  p.poses[2].x() = NAN;
  const std::vector<swslam::geometry::Pose2> before = p.poses;
  const auto rep = swslam::graph::optimizeGraphProblem(p, swslam::graph::GraphOptimizerParams{});
  EXPECT_EQ(rep.status, OptimizationStatus::Diverged);
  EXPECT_FALSE(rep.message.empty());
  for (size_t n = 0; n < 4; ++n)
    for (int k = 0; k < 3; ++k)
      if (!std::isnan(before[n][k])) EXPECT_EQ(p.poses[n][k], before[n][k]);
}

TEST(GraphOptimizer, NothingToOptimize)
{
  GraphProblem p = squareLoop(false);
  p.fixed = {1, 1, 1, 1};
  const std::vector<swslam::geometry::Pose2> before = p.poses;
  EXPECT_EQ(swslam::graph::optimizeGraphProblem(p, {}).status, OptimizationStatus::NothingToOptimize);
  EXPECT_EQ(p.poses, before);
}

TEST(GraphOptimizer, MaxIterationsIsRespected)
{
  GraphProblem p = squareLoop(false);
  swslam::graph::GraphOptimizerParams params;
  params.max_iterations = 1;
  const auto rep = swslam::graph::optimizeGraphProblem(p, params);
  EXPECT_EQ(rep.iterations, 1u);
  EXPECT_EQ(rep.status, OptimizationStatus::MaxIterations);
  EXPECT_LT(rep.final_cost, rep.initial_cost);
}

TEST(GraphOptimizer, RejectsMalformedProblems)
{
  GraphProblem p = squareLoop(false);
  p.edges[0].j = 7;
  EXPECT_THROW(swslam::graph::optimizeGraphProblem(p, {}), std::invalid_argument);
  p = squareLoop(false);
  p.edges[1].j = p.edges[1].i;
  EXPECT_THROW(swslam::graph::optimizeGraphProblem(p, {}), std::invalid_argument);
  p = squareLoop(false);
  p.fixed.pop_back();
  EXPECT_THROW(swslam::graph::optimizeGraphProblem(p, {}), std::invalid_argument);
}

TEST(GraphOptimizerParams, DefaultIniLoadsStrictlyAndRoundTrips)
{
  mrpt::config::CConfigFile ini(std::string(SWSLAM_SOURCE_DIR) + "/config/default.ini");
  const auto p = swslam::graph::GraphOptimizerParams::table().load(ini);
  // The file documents the in-class defaults.
  const swslam::graph::GraphOptimizerParams d;
  EXPECT_EQ(p.kernel_alpha, d.kernel_alpha);
  EXPECT_EQ(p.kernel_c, d.kernel_c);
  EXPECT_EQ(p.window_size, d.window_size);
  EXPECT_EQ(p.full_optimization_interval, d.full_optimization_interval);
  EXPECT_EQ(p.full_optimization_loop_xy, d.full_optimization_loop_xy);
  EXPECT_NEAR(p.full_optimization_loop_theta, d.full_optimization_loop_theta, 1e-15);
  EXPECT_EQ(p.max_iterations, d.max_iterations);
  EXPECT_EQ(p.lm_initial_lambda, d.lm_initial_lambda);
  EXPECT_EQ(p.lm_max_lambda, d.lm_max_lambda);
  EXPECT_EQ(p.relative_cost_tolerance, d.relative_cost_tolerance);
  EXPECT_EQ(p.step_tolerance, d.step_tolerance);
  EXPECT_EQ(p.gradient_tolerance, d.gradient_tolerance);
  EXPECT_EQ(p.robust_odometry_prior, d.robust_odometry_prior);
  EXPECT_EQ(p.max_iterations, 100u);  // the paper's value
  EXPECT_TRUE(p.isRobust(swslam::graph::EdgeKind::Consecutive));
  EXPECT_TRUE(p.isRobust(swslam::graph::EdgeKind::Loop));
  EXPECT_FALSE(p.isRobust(swslam::graph::EdgeKind::DenseNeighbour));

  mrpt::config::CConfigFileMemory mem;
  swslam::graph::GraphOptimizerParams q;
  q.kernel_alpha = swslam::graph::kAlphaWelsch;
  q.window_size = 12;
  q.full_optimization_interval = 7;
  swslam::graph::GraphOptimizerParams::table().save(q, mem);
  const auto r = swslam::graph::GraphOptimizerParams::table().load(mem);
  EXPECT_TRUE(std::isinf(r.kernel_alpha) && r.kernel_alpha < 0);
  EXPECT_EQ(r.window_size, 12u);
  EXPECT_EQ(r.full_optimization_interval, 7u);
}

TEST(GraphOptimizerParams, RejectsUnknownKeysAndBadValues)
{
  mrpt::config::CConfigFileMemory mem;
  mem.write("graph_optimizer", "kernel_alfa", 1.0);
  EXPECT_THROW(swslam::graph::GraphOptimizerParams::table().load(mem),
               std::invalid_argument);
  mrpt::config::CConfigFileMemory bad;
  bad.write("graph_optimizer", "kernel_alpha", 3.0);
  EXPECT_THROW(swslam::graph::GraphOptimizerParams::table().load(bad),
               std::invalid_argument);
  swslam::graph::GraphOptimizerParams p;
  p.window_size = 0;
  EXPECT_THROW(p.check(), std::invalid_argument);
  mrpt::config::CConfigFileMemory zero;
  zero.write("graph_optimizer", "full_optimization_interval", 0);
  EXPECT_THROW(swslam::graph::GraphOptimizerParams::table().load(zero),
               std::invalid_argument);
  for (const auto& [key, value] : {std::pair<const char*, double>{"full_optimization_loop_xy", -0.1},
                                   {"full_optimization_loop_theta_DEG", -1.0},
                                   {"full_optimization_loop_theta_DEG", 181.0}})
  {
    mrpt::config::CConfigFileMemory loop;
    loop.write("graph_optimizer", key, value);
    EXPECT_THROW(swslam::graph::GraphOptimizerParams::table().load(loop),
                 std::invalid_argument)
        << key << " = " << value;
  }
}

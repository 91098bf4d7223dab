// LAGO's starting point (initialization.h): the tree, the unwrapped rotations, the linear
// solves against a dense version, and a start from which least squares reaches the optimum an
// odometry guess misses.
#include <swslam/graph/initialization.h>

#include <swslam/graph/sliding_window.h>
#include <swslam/graph/synthetic.h>

#include "graph_test_support.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <set>

using namespace swslam::graph;
using swslam::geometry::Pose2;

namespace
{
GraphProblem::Edge edge(int i, int j, const Pose2& z, EdgeKind kind, double w_xy = 100, double w_theta = 1000)
{
  GraphProblem::Edge e;
  e.i = i;
  e.j = j;
  e.z = z;
  e.kind = kind;
  e.information = Eigen::Vector3d(w_xy, w_xy, w_theta).asDiagonal();
  return e;
}

/** A random problem: a chain of `n` poses and `loops` loops between random pairs, all with
 * random full information matrices; pose 0 fixed. */
GraphProblem randomProblem(int n, int loops, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(-1, 1);
  GraphProblem p;
  p.poses.assign(n, Pose2::Zero());
  p.fixed.assign(n, 0);
  p.fixed[0] = 1;
  p.poses[0] = Pose2(0.3, -0.2, 0.4);
  auto info = [&]() {
    Eigen::Matrix3d A;
    for (int k = 0; k < 9; k++) A(k / 3, k % 3) = U(rng);
    return Eigen::Matrix3d(A * A.transpose() + Eigen::Matrix3d::Identity());
  };
  for (int k = 1; k < n; k++)
  {
    auto e = edge(k - 1, k, Pose2(1 + 0.3 * U(rng), 0.3 * U(rng), 0.5 * U(rng)), EdgeKind::Consecutive);
    e.information = info();
    p.edges.push_back(e);
  }
  std::uniform_int_distribution<int> node(0, n - 1);
  for (int k = 0; k < loops; k++)
  {
    int i = node(rng), j = node(rng);
    if (i == j) continue;
    auto e = edge(i, j, Pose2(3 * U(rng), 3 * U(rng), 3 * U(rng)), EdgeKind::Loop);
    e.information = info();
    p.edges.push_back(e);
  }
  return p;
}
}  // namespace

TEST(LagoInitialization, TheTreeFollowsTheLeastHeadingVariance)
{
  GraphProblem p;
  p.poses.assign(6, Pose2::Zero());
  p.fixed.assign(6, 0);
  p.fixed[0] = 1;
  // Heading variances 1e-3 per odometry edge; the loop 0 -> 2 is known as well as one of them,
  // the loop 0 -> 3 only to 1e-2.
  p.edges = {edge(0, 1, Pose2(1, 0, 0), EdgeKind::Consecutive), edge(1, 2, Pose2(1, 0, 0), EdgeKind::Consecutive),
             edge(0, 2, Pose2(2, 0, 0), EdgeKind::Loop),        edge(2, 3, Pose2(1, 0, 0), EdgeKind::Consecutive),
             edge(0, 3, Pose2(3, 0, 0), EdgeKind::Loop, 100, 100), edge(4, 5, Pose2(1, 0, 0), EdgeKind::Consecutive)};
  const std::vector<int> tree = spanningTree(p);
  EXPECT_EQ(tree, (std::vector<int>{-1, 0, 2, 3, -1, 5}))
      << "2 by the loop (one edge's variance, not two), 3 along the chain from 2 (not the vaguer loop), 4 the "
         "first pose of a second piece";
}

TEST(LagoInitialization, RotationsAreUnwrappedToAgreeWithTheTree)
{
  GraphProblem p;
  p.poses.assign(3, Pose2::Zero());
  p.fixed = {1, 0, 0};
  p.edges = {edge(0, 1, Pose2(1, 0, 3.0), EdgeKind::Consecutive), edge(1, 2, Pose2(1, 0, 3.0), EdgeKind::Consecutive),
             edge(0, 2, Pose2(1, 0, 6.0 - 2 * M_PI), EdgeKind::Loop, 100, 100)};  // vaguer than the chain
  const std::vector<double> d = unwrappedRotations(p, spanningTree(p));
  EXPECT_DOUBLE_EQ(d[0], 3.0);
  EXPECT_DOUBLE_EQ(d[1], 3.0);
  EXPECT_NEAR(d[2], 6.0, 1e-12) << "the loop's -0.28 rad is the tree's +6 rad, a full turn apart";
}

TEST(LagoInitialization, TheLinearSolvesEqualDenseOnes)
{
  for (unsigned seed = 1; seed <= 5; seed++)
  {
    const GraphProblem p = randomProblem(30, 40, seed);
    const std::vector<Pose2> lago = lagoPoses(p);
    const std::vector<double> d = unwrappedRotations(p, spanningTree(p));
    const int n = static_cast<int>(p.poses.size());
    // Headings: dense normal equations with pose 0 held.
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    for (size_t k = 0; k < p.edges.size(); k++)
    {
      const auto& e = p.edges[k];
      const double w = 1 / e.information.inverse()(2, 2);
      A(e.i, e.i) += w, A(e.j, e.j) += w, A(e.i, e.j) -= w, A(e.j, e.i) -= w;
      b(e.i) -= w * d[k], b(e.j) += w * d[k];
    }
    A.row(0).setZero(), A.col(0).setZero(), A(0, 0) = 1, b(0) = 0;
    for (size_t k = 0; k < p.edges.size(); k++)  // pose 0's heading, held, on the other side
    {
      const auto& e = p.edges[k];
      const double w = 1 / e.information.inverse()(2, 2);
      if (e.i == 0) b(e.j) += w * p.poses[0].z();
      if (e.j == 0) b(e.i) += w * p.poses[0].z();
    }
    b(0) = p.poses[0].z();
    const Eigen::VectorXd theta = A.ldlt().solve(b);
    for (int q = 0; q < n; q++)
      EXPECT_NEAR(std::remainder(lago[q].z() - theta(q), 2 * M_PI), 0, 1e-9) << "seed " << seed << " pose " << q;
    // Positions: the weighted residuals of the linear problem are stationary at LAGO's answer
    // (the gradient of sum r' W r over the free positions is zero).
    Eigen::VectorXd g = Eigen::VectorXd::Zero(2 * n);
    for (const auto& e : p.edges)
    {
      const double c = std::cos(theta(e.i)), s = std::sin(theta(e.i));
      const Eigen::Matrix2d R = (Eigen::Matrix2d() << c, -s, s, c).finished();
      const Eigen::Matrix2d W = R * e.information.inverse().topLeftCorner<2, 2>().inverse() * R.transpose();
      const Eigen::Vector2d r = lago[e.j].head<2>() - lago[e.i].head<2>() - R * e.z.head<2>();
      g.segment<2>(2 * e.j) += W * r;
      g.segment<2>(2 * e.i) -= W * r;
    }
    EXPECT_LT(g.tail(2 * n - 2).lpNorm<Eigen::Infinity>(), 1e-8) << "seed " << seed;
    EXPECT_EQ(lago[0], p.poses[0]) << "the fixed pose is held";
  }
}

TEST(LagoInitialization, TheStartDoesNotDependOnTheGuessAndLeadsToTheOptimum)
{
  // Two laps of a 15 m circle (400 poses), noisy odometry, a loop every 20 poses between the laps.
  std::mt19937 rng(2);
  std::normal_distribution<double> N(0, 1);
  const int n = 400;
  auto between = [](const Pose2& a, const Pose2& b) {
    const double c = std::cos(a.z()), s = std::sin(a.z()), dx = b.x() - a.x(), dy = b.y() - a.y();
    return Pose2(c * dx + s * dy, -s * dx + c * dy, std::remainder(b.z() - a.z(), 2 * M_PI));
  };
  std::vector<Pose2> truth;
  for (int k = 0; k < n; k++)
  {
    const double a = 4 * M_PI * k / n;
    truth.emplace_back(15 * std::sin(a), 15 - 15 * std::cos(a), a);
  }
  GraphProblem p;
  p.fixed.assign(n, 0);
  p.fixed[0] = 1;
  for (int k = 1; k < n; k++)
    p.edges.push_back(edge(k - 1, k, between(truth[k - 1], truth[k]) + Pose2(0.05 * N(rng), 0.05 * N(rng), 0.04 * N(rng)),
                           EdgeKind::Consecutive, 400, 625));
  for (int k = 0; k + n / 2 < n; k += 20)
    p.edges.push_back(edge(k, k + n / 2, between(truth[k], truth[k + n / 2]) + Pose2(0.05 * N(rng), 0.05 * N(rng), 0.01 * N(rng)),
                           EdgeKind::Loop, 400, 1e4));
  GraphOptimizerParams l2;
  l2.kernel_alpha = 2;
  GraphProblem from_truth = p;
  from_truth.poses = truth;
  const double optimum = optimizeGraphProblem(from_truth, l2).final_chi2;
  // Two guesses: the truth itself, and every pose scattered by metres and turned at random.
  GraphProblem scattered = p;
  scattered.poses = truth;
  std::uniform_real_distribution<double> U(-3, 3);
  for (int k = 1; k < n; k++) scattered.poses[k] += Pose2(U(rng), U(rng), U(rng));
  p.poses = truth;
  const std::vector<Pose2> a = lagoPoses(p), b = lagoPoses(scattered);
  for (int k = 0; k < n; k++) EXPECT_TRUE(a[k].isApprox(b[k], 1e-9)) << "pose " << k << ": only the fixed pose counts";
  scattered.poses = b;
  const OptimizationReport from_lago = optimizeGraphProblem(scattered, l2);
  EXPECT_LT(from_lago.initial_chi2, 10 * optimum) << "LAGO starts near the optimum";
  EXPECT_NEAR(from_lago.final_chi2, optimum, 1e-6 * optimum);

  // A whole graph's optimization takes LAGO's start where the guess is poor, and says so...
  GraphProblem poor = p;
  poor.poses = truth;
  for (int k = 1; k < n; k++) poor.poses[k] += Pose2(U(rng), U(rng), U(rng));
  const OptimizationReport best = optimizeFromBestStart(poor, l2);
  EXPECT_TRUE(best.lago_start);
  EXPECT_NEAR(best.final_chi2, optimum, 1e-6 * optimum);
  // ...and keeps a good guess without a second run.
  GraphProblem good = from_truth, alone = from_truth;
  const OptimizationReport kept = optimizeFromBestStart(good, l2);
  EXPECT_FALSE(kept.lago_start);
  EXPECT_EQ(kept.iterations, optimizeGraphProblem(alone, l2).iterations) << "LAGO's start was not run";
  EXPECT_NEAR(kept.final_chi2, optimum, 1e-6 * optimum);
}

TEST(LagoInitialization, RobustLagoKeepsTheTrueLoopsAndDropsRandomFalseOnes)
{
  SyntheticGraph s = swslam::test::robustWalk();
  const std::vector<size_t> added = swslam::test::addAsManyFalseLoops(s.graph, 3);
  const std::set<size_t> false_loops(added.begin(), added.end());
  const GraphSubproblem sub = fullSubproblem(s.graph, GraphOptimizerParams{});
  const std::vector<char> every(sub.problem.edges.size(), 1);
  const RobustLago r = robustLagoPoses(sub.problem, every, OutlierGates{});
  size_t false_kept = 0, true_dropped = 0, true_loops = 0;
  for (size_t k = 0; k < sub.problem.edges.size(); ++k)
  {
    const bool is_false = false_loops.count(sub.edge_indices[k]) > 0;
    false_kept += is_false && r.inliers[k];
    if (!is_false && sub.problem.edges[k].kind == EdgeKind::Loop) ++true_loops, true_dropped += !r.inliers[k];
  }
  EXPECT_LT(false_kept, 0.02 * added.size()) << false_kept << " of " << added.size();
  EXPECT_LT(true_dropped, 0.05 * true_loops) << true_dropped << " of " << true_loops;
  // Its poses are near the truth (LAGO's approximation, not the optimum).
  double worst = 0;
  for (size_t n = 0; n < sub.node_ids.size(); ++n)
    worst = std::max(worst, (r.poses[n].head<2>() - s.truth[sub.node_ids[n]].head<2>()).norm());
  EXPECT_LT(worst, 1.0);
}

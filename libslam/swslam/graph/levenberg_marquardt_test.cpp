// The Levenberg-Marquardt core: where every edge coupled would make the factor dense, the exact
// solve (weak edges off the factor's pattern, conjugate gradients) takes the same steps as the
// fully coupled one; the damping is carried from one solve into the next.
#include <swslam/graph/levenberg_marquardt.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace swslam::graph;
using swslam::geometry::Pose2;

namespace
{
/** n poses on a circle, every pair joined by a measurement with noise, every 40th pair's
 * measurement false by metres; the guess perturbed. */
GraphProblem noisyClique(int n)
{
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::vector<Pose2> truth;
  for (int k = 0; k < n; ++k)
  {
    const double a = 2 * M_PI * k / n;
    truth.emplace_back(10 * std::cos(a), 10 * std::sin(a), a + M_PI / 2);
  }
  GraphProblem p;
  for (const Pose2& t : truth) p.poses.push_back(t + Pose2(noise(rng) * 5, noise(rng) * 5, noise(rng)));
  p.fixed.assign(n, 0);
  p.fixed[0] = 1;
  p.poses[0] = truth[0];
  int count = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
    {
      Pose2 z = swslam::geometry::relativePose(truth[i], truth[j]) + Pose2(noise(rng), noise(rng), noise(rng) / 10);
      if (++count % 40 == 0) z += Pose2(3, -2, 0.5);
      p.edges.push_back({i, j, z, Eigen::Vector3d(2500, 2500, 10000).asDiagonal(), true, EdgeKind::Loop});
    }
  return p;
}
}  // namespace

TEST(LevenbergMarquardt, AnExactSolveOffADenseFactorTakesTheCoupledSteps)
{
  const GraphProblem start = noisyClique(80);
  GraphOptimizerParams params;
  params.max_iterations = 30;
  const KindKernels geman_mcclure = uniformKernels({-2.0, 1.0});
  // From near the optimum, so that the false edges are weak from the start.
  GraphProblem near = start;
  optimizeWithKernels(near, params, geman_mcclure);
  for (auto& x : near.poses) x += Pose2(0.01, -0.01, 0.001);
  near.poses[0] = start.poses[0];

  GraphProblem all = near, exact = near;
  const OptimizationReport a = optimizeWithKernels(all, params, geman_mcclure, {nullptr, Coupling::All, nullptr});
  const OptimizationReport e = optimizeWithKernels(exact, params, geman_mcclure, {nullptr, Coupling::Exact, nullptr});
  EXPECT_EQ(a.cg_iterations, 0u);
  EXPECT_GT(e.cg_iterations, 0u);  // the weak edges were off the factor
  EXPECT_EQ(a.accepted_steps, e.accepted_steps);
  EXPECT_NEAR(a.final_cost, e.final_cost, 1e-9 * a.final_cost);
  double worst = 0;
  for (size_t k = 0; k < all.poses.size(); ++k) worst = std::max(worst, (all.poses[k] - exact.poses[k]).norm());
  EXPECT_LT(worst, 1e-6);
}

TEST(LevenbergMarquardt, TheDampingIsCarriedIntoTheNextSolve)
{
  GraphProblem p = noisyClique(20);
  GraphOptimizerParams params;
  const KindKernels l2 = uniformKernels({2.0, 1.0});
  double damping = 10 * params.lm_initial_lambda;  // out of range: starts at lm_initial_lambda
  CoupledSystem sys;
  const OptimizationReport first = optimizeWithKernels(p, params, l2, {&sys, Coupling::All, &damping});
  EXPECT_EQ(first.status, OptimizationStatus::Converged) << first.message;
  EXPECT_LT(damping, params.lm_initial_lambda);  // fell with the accepted steps
  // From the result, with the damping it ended at: at the optimum at once.
  const double carried = damping;
  const OptimizationReport again = optimizeWithKernels(p, params, l2, {&sys, Coupling::All, &damping});
  EXPECT_LE(again.iterations, 2u);
  EXPECT_LE(damping, carried * 10);
}

TEST(LevenbergMarquardt, EachComponentWithoutAFixedPoseIsHeldAtItsFirst)
{
  GraphProblem p;
  p.poses.assign(6, Pose2::Zero());
  p.fixed = {0, 0, 0, 0, 1, 0};
  for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 1}, {1, 2}, {3, 4}, {4, 5}})
  {
    GraphProblem::Edge e;
    e.i = i, e.j = j;
    p.edges.push_back(e);
  }
  size_t components = 0;
  const std::vector<int> var = variableIndex(p, components);
  EXPECT_EQ(components, 2u);
  EXPECT_EQ(var, (std::vector<int>{-1, 0, 1, 2, -1, 3}));  // 0 the gauge, 4 fixed
}

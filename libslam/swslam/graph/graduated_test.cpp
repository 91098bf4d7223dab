// Graduated non-convexity and the adaptive kernel against false loop closures, from the
// odometry guess: the kernel switches the false loops off and keeps every true edge, and the
// result is the optimum of the graph without them (with no false loop, the least-squares
// optimum).
#include <swslam/graph/graduated.h>
#include <swslam/graph/optimizer.h>
#include <swslam/graph/sliding_window.h>
#include <swslam/graph/synthetic.h>

#include <gtest/gtest.h>

#include <limits>
#include <set>

using namespace swslam::graph;

namespace
{
SyntheticGraph cleanGraph()
{
  SyntheticGraphOptions o;
  o.nodes = 400;
  o.total_edges = 1200;
  o.seed = 21;
  return makeGridWalkGraph(o);
}

/** The optimum of the graph without false loops (least squares, from the odometry guess). */
PoseGraph cleanOptimum(const SyntheticGraph& s)
{
  PoseGraph g = s.graph;
  GraphOptimizerParams l2;
  l2.kernel_alpha = 2;
  optimizeFull(g, l2);
  return g;
}

/** rmse of the node positions of `g` against those of `reference`. */
double distance(const PoseGraph& g, const PoseGraph& reference)
{
  return compareToTruth(g, truthFromGraph(reference)).rmse_xy;
}

GraphOptimizerParams gnc()
{
  GraphOptimizerParams p;
  p.kernel_alpha = -2;  // Geman-McClure: a false loop's influence goes to zero
  p.kernel_schedule = KernelSchedule::Gnc;
  return p;
}

/** Every edge robustified, the shape and scale of each kind estimated from its residuals. */
GraphOptimizerParams adaptive()
{
  GraphOptimizerParams p;
  p.kernel_schedule = KernelSchedule::Adaptive;
  return p;
}
}  // namespace

TEST(Gnc, TheScheduleLowersTheBoundStageByStageToTheTarget)
{
  GraphOptimizerParams p;
  p.kernel_schedule = KernelSchedule::Gnc;
  p.kernel_alpha = -2;
  p.gnc_alpha_step = 1;
  const std::vector<double> floors = {1, 0, -1, -2};
  const std::vector<Coupling> couplings = {Coupling::Exact, Coupling::DecoupleWeakAfresh, Coupling::DecoupleWeak,
                                           Coupling::DecoupleWeak};
  for (size_t k = 0; k < floors.size(); ++k)
  {
    const GraduatedStage s = graduatedStage(k, p);
    EXPECT_DOUBLE_EQ(s.alpha_floor, floors[k]) << "stage " << k;
    EXPECT_EQ(s.last, k + 1 == floors.size()) << "stage " << k;
    EXPECT_EQ(s.coupling, couplings[k]) << "stage " << k;
  }
  // A step past the target stops at it.
  p.gnc_alpha_step = 1.5;
  EXPECT_FALSE(graduatedStage(1, p).last);
  EXPECT_DOUBLE_EQ(graduatedStage(2, p).alpha_floor, -2);
  EXPECT_TRUE(graduatedStage(2, p).last);
  // Welsch's shape (-inf) is taken at once below -10.
  p.gnc_alpha_step = 1;
  p.kernel_alpha = -std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(graduatedStage(11, p).alpha_floor, -10);
  EXPECT_FALSE(graduatedStage(11, p).last);
  EXPECT_TRUE(graduatedStage(12, p).last);
  EXPECT_EQ(graduatedStage(12, p).alpha_floor, p.kernel_alpha);
  // The adaptive kernel's target is adaptive_alpha_min, every edge coupled.
  p.kernel_schedule = KernelSchedule::Adaptive;
  p.adaptive_alpha_min = -3;
  EXPECT_FALSE(graduatedStage(3, p).last);
  EXPECT_TRUE(graduatedStage(4, p).last);
  for (size_t k = 0; k < 5; ++k) EXPECT_EQ(graduatedStage(k, p).coupling, Coupling::All);
}

TEST(Gnc, WithoutOutliersItReachesLeastSquares)
{
  const SyntheticGraph s = cleanGraph();
  for (const GraphOptimizerParams& params : {gnc(), adaptive()})
  {
  SCOPED_TRACE(kernelScheduleName(params.kernel_schedule));
  PoseGraph g = s.graph;
  const OptimizationReport r = optimizeFull(g, params);
  // The status is the last solve's (least squares on the kept edges), not a capped stage's.
  EXPECT_EQ(r.status, OptimizationStatus::Converged) << r.message;
  // gnc: no edge that the target kernel would switch off after the convex stage, so it goes
  // straight to least squares; adaptive settles its estimate over more stages.
  if (params.kernel_schedule == KernelSchedule::Gnc)
    EXPECT_EQ(r.stages, 1u);
  else
    EXPECT_GT(r.stages, 1u);
  const PoseGraph l2 = cleanOptimum(s);
  const double chi2_l2 = graphChi2(fullSubproblem(l2, {}).problem);
  EXPECT_NEAR(r.final_chi2, chi2_l2, 1e-3 * chi2_l2);
  EXPECT_TRUE(r.switched_off.empty()) << r.switched_off.size() << " true edges switched off";
  }
}

TEST(Gnc, AdaptiveShapesFollowTheResiduals)
{
  // The odometry chain is clean: its shape is the highest allowed (adaptive_alpha_max, 0 as in
  // config/default.ini); the loops with false ones among them get a heavier tail.
  const SyntheticGraph s = cleanGraph();
  PoseGraph g = s.graph;
  FalseLoopOptions fo;
  fo.count = 100;
  fo.seed = 5;
  addFalseLoops(g, fo);
  const OptimizationReport r = optimizeFull(g, adaptive());
  ASSERT_NE(r.status, OptimizationStatus::Diverged) << r.message;
  EXPECT_EQ(r.kernels[static_cast<int>(EdgeKind::Consecutive)].alpha, 0.0);
  EXPECT_LT(r.kernels[static_cast<int>(EdgeKind::Loop)].alpha, -0.5);
}

TEST(Gnc, FalseLoopsAreSwitchedOffRandomOrGrouped)
{
  const SyntheticGraph s = cleanGraph();
  const PoseGraph clean = cleanOptimum(s);
  for (const bool grouped : {false, true})
  {
    PoseGraph g = s.graph;
    FalseLoopOptions fo;
    fo.count = 100;
    fo.grouped = grouped;
    fo.seed = 3;
    const std::vector<size_t> added = addFalseLoops(g, fo);
    ASSERT_EQ(added.size(), fo.count);

    PoseGraph fixed = g;  // the paper's fixed Cauchy kernel from the odometry guess
    optimizeFull(fixed, GraphOptimizerParams());
    for (const GraphOptimizerParams& params : {gnc(), adaptive()})
    {
    SCOPED_TRACE(kernelScheduleName(params.kernel_schedule));
    PoseGraph result = g;
    const OptimizationReport r = optimizeFull(result, params);
    ASSERT_NE(r.status, OptimizationStatus::Diverged) << r.message;
    EXPECT_LT(distance(result, clean), 0.05) << "grouped " << grouped;
    EXPECT_LE(distance(result, clean), distance(fixed, clean)) << "grouped " << grouped;
    // The switched-off edges (graph edge indices) are exactly the false loops.
    const std::set<size_t> off(r.switched_off.begin(), r.switched_off.end()), truth(added.begin(), added.end());
    EXPECT_EQ(off, truth) << "grouped " << grouped;
    }
  }
}

TEST(Gnc, ManyFalseLoopsAreSolvedWithASparseFactor)
{
  // Enough long false loops that the factor with every edge coupled is dense: the convex
  // stage leaves the weak ones out of the factor and brings them back by conjugate gradients
  // (exactly: the same result as the clean optimum, every false loop switched off).
  const SyntheticGraph s = cleanGraph();
  const PoseGraph clean = cleanOptimum(s);
  PoseGraph g = s.graph;
  FalseLoopOptions fo;
  fo.count = 400;
  fo.seed = 8;
  const std::vector<size_t> added = addFalseLoops(g, fo);
  const OptimizationReport r = optimizeFull(g, gnc());
  ASSERT_NE(r.status, OptimizationStatus::Diverged) << r.message;
  EXPECT_GT(r.cg_iterations, 0u);
  EXPECT_LT(distance(g, clean), 0.05);
  const std::set<size_t> off(r.switched_off.begin(), r.switched_off.end()), truth(added.begin(), added.end());
  EXPECT_EQ(off, truth);
}

#include <swslam/graph/graduated.h>

#include <swslam/graph/adaptive_kernel.h>
#include <swslam/graph/levenberg_marquardt.h>

#include <mrpt/system/CTicTac.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace swslam::graph
{
namespace
{
/** Adaptive: a kind with fewer robustified edges than this keeps the configured kernel. */
constexpr size_t kAdaptiveMinEdges = 10;

/** Per edge kind with robustified edges: the shape that fits its residuals at the problem's
 * poses best, within [alpha_floor, alpha_cap], and the scale kernel_c, times the robust scale
 * of the residuals if `scaled` (KernelSchedule::Adaptive: the stages keep kernel_c, since from
 * a poor guess every residual is large and a wide scale would let the false edges pull; the
 * kernels at the result are scaled). `limited` tells whether the floor held a shape. */
KindKernels estimateKernels(const GraphProblem& p, const GraphOptimizerParams& params,
                            const ShapeEstimator& shapes, double alpha_floor, double alpha_cap, bool scaled,
                            bool& limited)
{
  const std::vector<double> r = robustResiduals(p);
  std::array<std::vector<double>, kEdgeKindCount> by_kind;
  for (size_t n = 0; n < p.edges.size(); ++n)
    if (p.edges[n].robust) by_kind[static_cast<int>(p.edges[n].kind)].push_back(r[n]);
  KindKernels k = uniformKernels(params.kernel());
  limited = false;
  for (int kind = 0; kind < kEdgeKindCount; ++kind)
  {
    if (by_kind[kind].empty()) continue;
    // Too few residuals tell no distribution (one false loop alone would be its own scale):
    // such a kind keeps the configured kernel, graduated like gnc.
    const bool estimated = by_kind[kind].size() >= kAdaptiveMinEdges;
    // The information matrices bound the precision: residuals tighter than they say (exact
    // simulated measurements) do not shrink the scale below kernel_c.
    const double c =
        estimated && scaled ? params.kernel_c * std::max(1.0, robustResidualScale(by_kind[kind])) : params.kernel_c;
    const double alpha = estimated ? shapes.estimate(by_kind[kind], c).alpha : params.kernel_alpha;
    limited = limited || alpha < alpha_floor;
    k[kind] = {std::min(alpha_cap, std::max(alpha, alpha_floor)), c};
  }
  return k;
}

/** Whether two stages' kernels agree: each shape within half a grid step, each scale within
 * 5%. */
bool settled(const KindKernels& a, const KindKernels& b, double alpha_step)
{
  for (int kind = 0; kind < kEdgeKindCount; ++kind)
    if (std::abs(a[kind].alpha - b[kind].alpha) > 0.5 * alpha_step + 1e-12 ||
        std::abs(a[kind].c - b[kind].c) > 0.05 * std::max(a[kind].c, b[kind].c))
      return false;
  return true;
}

/** Rounds of least squares on the kept edges at most. */
constexpr size_t kMaxRefits = 3;

/** Least squares on the edges not in `off` (increasing indices), from the problem's poses,
 * which take the result unless it diverged. Without the false edges the system is sparse. */
OptimizationReport leastSquaresOnKept(GraphProblem& problem, const std::vector<size_t>& off,
                                      const GraphOptimizerParams& params, CoupledSystem& sys,
                                      double* damping)
{
  GraphProblem kept = problem;
  kept.edges.clear();
  for (size_t n = 0, k = 0; n < problem.edges.size(); ++n)
  {
    if (k < off.size() && off[k] == n)
      ++k;
    else
      kept.edges.push_back(problem.edges[n]);
  }
  const OptimizationReport r = optimizeWithKernels(kept, params, uniformKernels({2.0, params.kernel_c}), {&sys, Coupling::All, damping});  // the kept edges: sparse
  if (r.status != OptimizationStatus::Diverged) problem.poses = kept.poses;
  return r;
}

/** Least squares on the edges that `kernels` keep at the problem's poses (weight at least
 * switched_off_weight), then again while the kept set changes: an edge left out that agrees
 * with the result is taken back (at most kMaxRefits rounds). If a kept edge is switched off
 * at a result, the stages may have left the poses in another basin of the inliers' optimum
 * (a long chain bent the other way): that round is also solved from the `given` poses, once,
 * and the lower chi2 wins. Only then, since the second start costs a whole solve. The
 * rounds go on with the `damping` of the solve before them (the second start from the
 * initial damping). `kept` receives the number of edges kept; the iterations are added to `total`. */
OptimizationReport refitKept(GraphProblem& problem, const KindKernels& kernels, const std::vector<geometry::Pose2>& given,
                             const GraphOptimizerParams& params, CoupledSystem& sys, double& damping,
                             size_t& kept, OptimizationReport& total)
{
  std::vector<size_t> off = switchedOffEdges(problem, kernels, params.switched_off_weight);
  bool second_start = false;
  OptimizationReport refit;
  for (size_t round = 0; round < kMaxRefits; ++round)
  {
    const std::vector<geometry::Pose2> start = problem.poses;
    refit = leastSquaresOnKept(problem, off, params, sys, &damping);
    kept = problem.edges.size() - off.size();
    total.iterations += refit.iterations;
    total.accepted_steps += refit.accepted_steps;
    std::vector<size_t> again = switchedOffEdges(problem, kernels, params.switched_off_weight);
    const bool doubt = refit.status == OptimizationStatus::Diverged ||
                       !std::includes(off.begin(), off.end(), again.begin(), again.end());
    if (doubt && !second_start && start != given)
    {
      second_start = true;
      GraphProblem other = problem;
      other.poses = given;
      const OptimizationReport b = leastSquaresOnKept(other, off, params, sys, nullptr);
      total.iterations += b.iterations;
      total.accepted_steps += b.accepted_steps;
      if (b.status != OptimizationStatus::Diverged &&
          (refit.status == OptimizationStatus::Diverged || b.final_chi2 < refit.final_chi2))
      {
        problem.poses = other.poses;
        refit = b;
        again = switchedOffEdges(problem, kernels, params.switched_off_weight);
      }
    }
    if (refit.status == OptimizationStatus::Diverged || again == off) break;
    off.swap(again);
  }
  return refit;
}

/** gnc: the share of the edges switched off by the target kernel after a stage up to which the
 * graduation ends there. */
constexpr double kFewOutliers = 0.01;
/** gnc: only a problem with at least this many edges ends its graduation early. In a small one
 * the convex stage can absorb a false loop: in the room loop of GraphModule's test (17 edges,
 * every one robustified), one confident false loop bent the ring so that the target kernel
 * switched nothing off after the first stage, and least squares then kept it (0.84 m off).
 * Among thousands of edges a few false loops cannot bend the graph that far. */
constexpr size_t kMinEdgesForEarlyEnd = 1000;

/** Graduated stages stop lowering the shape's bound here; a lower target comes next. */
constexpr double kLowestGraduatedAlpha = -10.0;

/** Adds stage k's report `s` to the run's. */
void addStage(OptimizationReport& total, const OptimizationReport& s, size_t k)
{
  if (k == 0)
    total = s;
  else
  {
    total.iterations += s.iterations;
    total.accepted_steps += s.accepted_steps;
    total.cg_iterations += s.cg_iterations;
    total.status = s.status;
    total.message = s.message;
  }
  total.stages = k + 1;
}

/** gnc: little outlier evidence, at most kFewOutliers of the edges that the target kernel
 * would switch off at the problem's poses, in a problem of kMinEdgesForEarlyEnd edges or more.
 * Then least squares on the others follows at once: with none, the lower shapes would weigh
 * every edge about as least squares does; with a few, the graph's poses are already near the
 * inliers' optimum, and the refit rounds take back an edge that agrees with it and take out one
 * the graph had absorbed. */
bool fewOutliersLeft(const GraphProblem& problem, const GraphOptimizerParams& params)
{
  if (problem.edges.size() < kMinEdgesForEarlyEnd) return false;
  const size_t off = switchedOffEdges(problem, uniformKernels(params.kernel()), params.switched_off_weight).size();
  return static_cast<double>(off) <= kFewOutliers * static_cast<double>(problem.edges.size());
}

/** The run ended early with `message`; the problem's poses go back to `given` if `restore`. */
OptimizationReport ended(OptimizationReport total, GraphProblem& problem, const std::vector<geometry::Pose2>& given,
                         bool restore, const std::string& message, mrpt::system::CTicTac& timer)
{
  if (restore) problem.poses = given;
  total.message = message;
  total.time_s = timer.Tac();
  return total;
}

}  // namespace

GraduatedStage graduatedStage(size_t k, const GraphOptimizerParams& params)
{
  const bool adaptive = params.kernel_schedule == KernelSchedule::Adaptive;
  const double target = adaptive ? params.adaptive_alpha_min : params.kernel_alpha;
  GraduatedStage stage;
  stage.alpha_floor = 1.0 - static_cast<double>(k) * params.gnc_alpha_step;
  stage.last = stage.alpha_floor <= target || stage.alpha_floor < kLowestGraduatedAlpha;
  if (stage.last) stage.alpha_floor = target;
  // The convex first stage solves exactly, every edge coupled: from the given poses the true
  // loops are as far off as the false ones (drift), and decoupling them there spoiled the stage
  // (with no false loop, 145 edges decoupled after its first step, and 69 true edges ended
  // switched off by the target kernel instead of none). Where that factor is dense (a thousand
  // long false loops), the weak edges are solved by conjugate gradients off the factor's
  // pattern instead (Coupling::Exact). The next stage starts with every edge coupled again,
  // then decouples those weak at its own poses. The adaptive kernel decouples nothing: with
  // it, 100 random false loops ended 0.027 m off with a true edge switched off, against
  // 0.0004 m.
  stage.coupling = adaptive ? Coupling::All
                   : k == 0 ? Coupling::Exact
                   : k == 1 ? Coupling::DecoupleWeakAfresh
                            : Coupling::DecoupleWeak;
  return stage;
}

OptimizationReport optimizeGraduated(GraphProblem& problem, const GraphOptimizerParams& params)
{
  mrpt::system::CTicTac timer;
  params.check();
  checkProblem(problem);
  const bool adaptive = params.kernel_schedule == KernelSchedule::Adaptive;
  const ShapeEstimator* shapes =
      adaptive ? &shapeEstimatorFor(params.adaptive_alpha_min, params.adaptive_alpha_max, params.adaptive_alpha_step,
                                  params.adaptive_truncation)
               : nullptr;
  const std::vector<geometry::Pose2> given = problem.poses;
  GraphOptimizerParams stage = params;
  stage.max_iterations = std::min(params.max_iterations, params.gnc_stage_iterations);
  CoupledSystem sys;  // one pattern for every stage (their edges are the same)
  double damping = 0;  // carried from stage to stage and into the least squares after them
  OptimizationReport total;
  KindKernels kernels, previous;
  for (size_t k = 0;; ++k)
  {
    const GraduatedStage g = graduatedStage(k, params);
    bool limited = !g.last;  // gnc: the stages go on down to the target
    kernels = adaptive ? estimateKernels(problem, params, *shapes, g.alpha_floor, 1.0, false, limited)
                       : uniformKernels({g.alpha_floor, params.kernel_c});
    const OptimizationReport s = optimizeWithKernels(problem, stage, kernels, {&sys, g.coupling, &damping});
    addStage(total, s, k);
    if (k == 0) total.initial_cost = evaluate(problem, given, kernels, measurementRotations(problem)).cost;
    if (s.status == OptimizationStatus::Diverged)
      return ended(total, problem, given, true, "stage " + std::to_string(k + 1) + ": " + s.message, timer);
    if (s.status == OptimizationStatus::NothingToOptimize) return ended(total, problem, given, false, s.message, timer);
    // Done at the last bound, or (adaptive) when the bound no longer holds a shape back and
    // the estimate has settled: from a poor guess every residual is large, so the first
    // scales are wide and the shapes near 2 until the poses come near the inliers.
    if (g.last || (!limited && k > 0 && settled(previous, kernels, params.adaptive_alpha_step))) break;
    if (!adaptive && fewOutliersLeft(problem, params))
    {
      kernels = uniformKernels(params.kernel());
      break;
    }
    previous = kernels;
  }
  // The kernels at the result decide which edges are kept.
  if (adaptive)
  {
    bool limited = false;
    kernels = estimateKernels(problem, params, *shapes, params.adaptive_alpha_min, 2.0, true, limited);
  }
  size_t kept = 0;
  const OptimizationReport refit = refitKept(problem, kernels, given, params, sys, damping, kept, total);
  total.status = refit.status;
  if (refit.status == OptimizationStatus::Diverged)
    return ended(total, problem, given, true, "the least-squares solve on the kept edges: " + refit.message, timer);
  const Evaluation end = evaluate(problem, problem.poses, kernels, measurementRotations(problem));
  total.kernels = kernels;
  total.final_chi2 = end.chi2;
  total.final_cost = end.cost;
  total.active_sq_residuals = end.active;
  total.message = std::string(adaptive ? "adaptive kernel" : "graduated non-convexity") + ", " +
                  std::to_string(total.stages) + " stages, then least squares on the " +
                  std::to_string(kept) + " edges kept: " + refit.message;
  total.time_s = timer.Tac();
  return total;
}

}  // namespace swslam::graph

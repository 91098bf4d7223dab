#pragma once
// Graduated non-convexity (KernelSchedule::Gnc) and the adaptive kernel (::Adaptive): stages of
// a few Levenberg-Marquardt iterations each (levenberg_marquardt.h), the kernel's shape bounded
// below by 1 (convex), then lower stage by stage, each stage from the last one's poses and with
// its coupling policy (coupling_policy.h); then least squares on the edges the last stage's
// kernel kept, so that their noise is not down-weighted (with no outlier this is the
// least-squares optimum). doc/graph-optimization.md, "Graduated non-convexity".

#include <swslam/graph/coupling_policy.h>
#include <swslam/graph/optimizer.h>

#include <cstddef>

namespace swslam::graph
{
/** Stage k of the graduation (k from 0). */
struct GraduatedStage
{
  /** The bound below the kernel's shape: 1 (convex), then lower by gnc_alpha_step each stage,
   * down to the target (kernel_alpha; adaptive: adaptive_alpha_min), which a shape below -10
   * takes at once. */
  double alpha_floor = 1.0;
  bool last = false;  ///< the bound is the target
  /** Which edges the stage solves in the factor: gnc solves its convex first stage exactly,
   * the next from every edge coupled, then decouples the weak ones; adaptive couples all. */
  Coupling coupling = Coupling::All;
};
GraduatedStage graduatedStage(size_t k, const GraphOptimizerParams& params);

/** The graduated optimization of params' schedule (Gnc or Adaptive), from the problem's poses;
 * on Diverged the poses are left as given. */
OptimizationReport optimizeGraduated(GraphProblem& problem, const GraphOptimizerParams& params);

}  // namespace swslam::graph

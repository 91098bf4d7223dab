#pragma once
// Graduated non-convexity (KernelSchedule::Gnc) and the adaptive kernel (::Adaptive): stages of
// a few Levenberg-Marquardt iterations each (levenberg_marquardt.h), the kernel's shape bounded
// below by 1 (convex), then lower stage by stage, each stage from the last one's poses and with
// its coupling policy (coupling_policy.h); then least squares on the edges the last stage's
// kernel kept, so that their noise is not down-weighted (with no outlier this is the
// least-squares optimum). doc/graph-optimization.md, "Graduated non-convexity".

#include <swslam/graph/optimizer.h>

namespace swslam::graph
{
/** The graduated optimization of params' schedule (Gnc or Adaptive), from the problem's poses;
 * on Diverged the poses are left as given. */
OptimizationReport optimizeGraduated(GraphProblem& problem, const GraphOptimizerParams& params);

}  // namespace swslam::graph

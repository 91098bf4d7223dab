#pragma once
// Levenberg-Marquardt with IRLS reweighting at every linearization (paper eq. 11-13): the core
// that every kernel schedule runs (optimizer.h dispatches; graduated.h runs it per stage). The
// normal equations are sparse 3x3 blocks (normal_equations.h), the edges coupled in them as the
// coupling policy says (coupling_policy.h).

#include <swslam/geometry/se2_error.h>
#include <swslam/graph/coupling_policy.h>
#include <swslam/graph/optimizer.h>

#include <vector>

namespace swslam::graph
{
/** A problem's cost at some poses: the robust cost, chi2, and sum of w r^2 (eq. 11). */
struct Evaluation
{
  double cost = 0, chi2 = 0, active = 0;
};

/** sin/cos of each measurement's angle (once per problem). */
std::vector<geometry::SinCos> measurementRotations(const GraphProblem& p);

/** sin/cos of each pose's angle, shared by the pose's edges. */
std::vector<geometry::SinCos> poseRotations(const std::vector<geometry::Pose2>& x);

/** The problem's cost at poses x under kernel k per edge kind (rz: measurementRotations). */
Evaluation evaluate(const GraphProblem& p, const std::vector<geometry::Pose2>& x, const KindKernels& k,
                    const std::vector<geometry::SinCos>& rz);

/** Per edge, whether its IRLS weight at x is below `weight` (robustified edges only). */
std::vector<char> weakEdges(const GraphProblem& p, const std::vector<geometry::Pose2>& x, const KindKernels& k,
                            const std::vector<geometry::SinCos>& rz, double weight);

/** Per pose, the lowest pose index of its connected component (edges joining poses). */
std::vector<int> componentRoots(const GraphProblem& p);

/** Variable index per pose (-1: held fixed). A connected component with no fixed pose is
 * held at its first pose (its gauge): otherwise nothing would tie it down. `components`
 * receives their number. */
std::vector<int> variableIndex(const GraphProblem& p, size_t& components);

/** The optimization with the given kernel per edge kind, from the problem's poses, which take
 * the result unless it diverged; `use` says how the normal equations are kept. */
OptimizationReport optimizeWithKernels(GraphProblem& problem, const GraphOptimizerParams& params,
                                       const KindKernels& kernels, const SystemUse& use = {});

}  // namespace swslam::graph

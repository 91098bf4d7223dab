#include <swslam/graph/optimizer.h>

#include <swslam/graph/graduated.h>
#include <swslam/graph/levenberg_marquardt.h>
#include <swslam/graph/outlier_decision.h>
#include <swslam/graph/robust_kernel.h>

#include <stdexcept>
#include <string>

namespace swslam::graph
{
const char* statusName(OptimizationStatus s)
{
  switch (s)
  {
    case OptimizationStatus::Converged: return "converged";
    case OptimizationStatus::MaxIterations: return "max_iterations";
    case OptimizationStatus::NothingToOptimize: return "nothing_to_optimize";
    case OptimizationStatus::Diverged: return "diverged";
  }
  return "?";
}

double graphChi2(const GraphProblem& problem)
{
  return evaluate(problem, problem.poses, uniformKernels({2.0, 1.0}), measurementRotations(problem)).chi2;
}

double robustCost(const GraphProblem& problem, const KindKernels& kernels)
{
  return evaluate(problem, problem.poses, kernels, measurementRotations(problem)).cost;
}

void checkProblem(const GraphProblem& p)
{
  if (p.fixed.size() != p.poses.size())
    throw std::invalid_argument("graph problem: 'fixed' and 'poses' differ in size");
  const int n = static_cast<int>(p.poses.size());
  for (size_t k = 0; k < p.edges.size(); ++k)
  {
    const auto& e = p.edges[k];
    if (e.i < 0 || e.j < 0 || e.i >= n || e.j >= n || e.i == e.j)
      throw std::invalid_argument("graph problem: edge " + std::to_string(k) + " joins poses " +
                                  std::to_string(e.i) + " and " + std::to_string(e.j) +
                                  " of " + std::to_string(n));
  }
}

std::vector<double> robustResiduals(const GraphProblem& problem)
{
  const std::vector<geometry::SinCos> rz = measurementRotations(problem);
  const std::vector<geometry::SinCos> rx = poseRotations(problem.poses);
  std::vector<double> r(problem.edges.size(), 0.0);
  for (size_t n = 0; n < problem.edges.size(); ++n)
  {
    const auto& e = problem.edges[n];
    if (!e.robust) continue;
    const Eigen::Vector3d err = geometry::se2Error(problem.poses[e.i], problem.poses[e.j], e.z, rx[e.i], rz[n]);
    r[n] = std::sqrt(err.dot(e.information * err));
  }
  return r;
}

KindKernels uniformKernels(const BarronKernel& k)
{
  KindKernels all;
  all.fill(k);
  return all;
}

std::vector<size_t> switchedOffEdges(const GraphProblem& problem, const KindKernels& kernels, double weight)
{
  const std::vector<double> r = robustResiduals(problem);
  std::vector<size_t> off;
  for (size_t n = 0; n < problem.edges.size(); ++n)
  {
    const auto& e = problem.edges[n];
    if (e.robust && normalizedBarronWeight(r[n], kernels[static_cast<int>(e.kind)]) < weight) off.push_back(n);
  }
  return off;
}

std::vector<size_t> switchedOffEdges(const GraphProblem& problem, const GraphOptimizerParams& params)
{
  return switchedOffEdges(problem, uniformKernels(params.kernel()), params.switched_off_weight);
}

OptimizationReport optimizeGraphProblem(GraphProblem& problem, const GraphOptimizerParams& params)
{
  if (params.kernel_schedule == KernelSchedule::Tls) return optimizeTruncated(problem, params);
  OptimizationReport rep = params.kernel_schedule == KernelSchedule::Fixed
                               ? optimizeWithKernels(problem, params, uniformKernels(params.kernel()))
                               : optimizeGraduated(problem, params);
  // Which robustified edges the kernel has switched off at the result.
  if (rep.status != OptimizationStatus::NothingToOptimize)
    rep.switched_off = switchedOffEdges(problem, rep.kernels, params.switched_off_weight);
  return rep;
}

}  // namespace swslam::graph

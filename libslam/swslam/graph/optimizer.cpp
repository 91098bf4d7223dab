#include <swslam/graph/optimizer.h>

#include <swslam/graph/normal_equations.h>

#include <mrpt/system/CTicTac.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace swslam::graph
{
namespace
{
/** Robust cost of one edge with Mahalanobis residual r, and its IRLS weight (eq. 13). */
struct EdgeCost
{
  double cost, weight;
};

EdgeCost edgeCost(double r, bool robust, const BarronKernel& kernel)
{
  if (!robust) return {0.5 * r * r, 1.0};
  return {normalizedBarronRho(r, kernel), normalizedBarronWeight(r, kernel)};
}

struct Evaluation
{
  double cost = 0, chi2 = 0, active = 0;
};

/** sin/cos of each measurement's angle (once per problem). */
std::vector<geometry::SinCos> measurementRotations(const GraphProblem& p)
{
  std::vector<geometry::SinCos> r;
  r.reserve(p.edges.size());
  for (const auto& e : p.edges) r.push_back(geometry::sinCos(e.z.z()));
  return r;
}

/** sin/cos of each pose's angle, shared by the pose's edges. */
std::vector<geometry::SinCos> poseRotations(const std::vector<geometry::Pose2>& x)
{
  std::vector<geometry::SinCos> r;
  r.reserve(x.size());
  for (const auto& pose : x) r.push_back(geometry::sinCos(pose.z()));
  return r;
}

Evaluation evaluate(const GraphProblem& p, const std::vector<geometry::Pose2>& x, const BarronKernel& k,
                    const std::vector<geometry::SinCos>& rz)
{
  Evaluation ev;
  const std::vector<geometry::SinCos> rx = poseRotations(x);
  for (size_t n = 0; n < p.edges.size(); ++n)
  {
    const auto& e = p.edges[n];
    const Eigen::Vector3d err = geometry::se2Error(x[e.i], x[e.j], e.z, rx[e.i], rz[n]);
    const double r2 = err.dot(e.information * err);
    const EdgeCost c = edgeCost(std::sqrt(r2), e.robust, k);
    ev.cost += c.cost;
    ev.chi2 += r2;
    ev.active += c.weight * r2;
  }
  return ev;
}

/** Fills H and g with the IRLS-weighted Gauss-Newton terms at x (eq. 11-13). */
void linearize(const GraphProblem& p, const std::vector<geometry::Pose2>& x, const std::vector<int>& var,
               const BarronKernel& k, const std::vector<geometry::SinCos>& rz, NormalEquations& ne)
{
  ne.setZero();
  Eigen::VectorXd& g = ne.gradient();
  Eigen::Matrix3d Ji, Jj;
  const std::vector<geometry::SinCos> rx = poseRotations(x);
  for (size_t n = 0; n < p.edges.size(); ++n)
  {
    const auto& e = p.edges[n];
    const int a = var[e.i], b = var[e.j];
    if (a < 0 && b < 0) continue;
    const Eigen::Vector3d err =
        geometry::se2ErrorWithJacobians(x[e.i], x[e.j], e.z, rx[e.i], rz[n], Ji, Jj);
    const double r = std::sqrt(err.dot(e.information * err));
    const Eigen::Matrix3d W = edgeCost(r, e.robust, k).weight * e.information;
    const Eigen::Vector3d We = W * err;
    if (a >= 0)
    {
      ne.addDiagonal(a, Ji.transpose() * W * Ji);
      g.segment<3>(3 * a) += Ji.transpose() * We;
    }
    if (b >= 0)
    {
      ne.addDiagonal(b, Jj.transpose() * W * Jj);
      g.segment<3>(3 * b) += Jj.transpose() * We;
    }
    if (a >= 0 && b >= 0) ne.addOffDiagonal(a, b, Ji.transpose() * W * Jj);
  }
}

void applyStep(const std::vector<int>& var, const Eigen::VectorXd& dx, std::vector<geometry::Pose2>& x)
{
  for (size_t n = 0; n < x.size(); ++n)
  {
    if (var[n] < 0) continue;
    x[n] += dx.segment<3>(3 * var[n]);
    x[n].z() = geometry::wrapAngle(x[n].z());
  }
}

/** Per pose, the lowest pose index of its connected component (edges joining poses). */
std::vector<int> componentRoots(const GraphProblem& p)
{
  std::vector<int> parent(p.poses.size());
  for (size_t n = 0; n < parent.size(); ++n) parent[n] = static_cast<int>(n);
  auto root = [&](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  for (const auto& e : p.edges)
  {
    const int a = root(e.i), b = root(e.j);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the lower index stays the root
  }
  std::vector<int> roots(parent.size());
  for (size_t n = 0; n < roots.size(); ++n) roots[n] = root(static_cast<int>(n));
  return roots;
}

/** Variable index per pose (-1: held fixed). A connected component with no fixed pose is
 * held at its first pose (its gauge): otherwise nothing would tie it down. */
std::vector<int> variableIndex(const GraphProblem& p, size_t& components)
{
  const std::vector<int> roots = componentRoots(p);
  std::vector<char> held(p.poses.size(), 0);  // per component root: it has a fixed pose
  components = 0;
  for (size_t n = 0; n < roots.size(); ++n)
  {
    components += roots[n] == static_cast<int>(n);
    if (p.fixed[n]) held[roots[n]] = 1;
  }
  std::vector<int> var(p.poses.size(), -1);
  int free_count = 0;
  for (size_t n = 0; n < var.size(); ++n)
  {
    const bool gauge = roots[n] == static_cast<int>(n) && !held[n];
    if (!(p.fixed[n] || gauge)) var[n] = free_count++;
  }
  return var;
}

struct Outcome
{
  OptimizationStatus status = OptimizationStatus::MaxIterations;
  std::string why = "reached max_iterations";
};

/** Levenberg-Marquardt with IRLS reweighting at every linearization (eq. 11-13). Updates x
 * and ev (its evaluation) on every accepted step, and the iteration counts of rep. */
Outcome levenbergMarquardt(const GraphProblem& p, const std::vector<int>& var,
                           const GraphOptimizerParams& params, const std::vector<geometry::SinCos>& rz,
                           std::vector<geometry::Pose2>& x, Evaluation& ev, OptimizationReport& rep)
{
  const BarronKernel kernel = params.kernel();
  std::vector<std::pair<int, int>> pairs;
  for (const auto& e : p.edges)
    if (var[e.i] >= 0 && var[e.j] >= 0) pairs.emplace_back(var[e.i], var[e.j]);
  NormalEquations ne(static_cast<int>(rep.free_nodes), pairs);

  double lambda = params.lm_initial_lambda, nu = 2.0;
  Eigen::VectorXd dx;
  bool relinearize = true;
  while (rep.iterations < params.max_iterations)
  {
    if (relinearize) linearize(p, x, var, kernel, rz, ne);
    relinearize = false;
    if (ne.gradient().lpNorm<Eigen::Infinity>() < params.gradient_tolerance)
      return {OptimizationStatus::Converged, "gradient below tolerance"};
    ++rep.iterations;
    const bool solved = ne.solveDamped(lambda, dx);
    std::vector<geometry::Pose2> x_new = x;
    if (solved) applyStep(var, dx, x_new);
    const Evaluation ev_new = solved ? evaluate(p, x_new, kernel, rz) : Evaluation{};
    const double decrease = ev.cost - ev_new.cost;
    const double predicted = solved ? ne.predictedDecrease(lambda, dx) : 0.0;
    if (solved && std::isfinite(ev_new.cost) && decrease > 0 && predicted > 0)
    {
      // Accepted: shrink the damping by the gain ratio (Nielsen's rule).
      lambda *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * decrease / predicted - 1.0, 3));
      nu = 2.0;
      x.swap(x_new);
      ev = ev_new;
      ++rep.accepted_steps;
      relinearize = true;
      double x_norm2 = 0;
      for (const auto& pose : x) x_norm2 += pose.squaredNorm();
      if (!std::isfinite(ev.cost) || !std::isfinite(x_norm2))
        return {OptimizationStatus::Diverged, "estimate became non-finite"};
      if (decrease <= params.relative_cost_tolerance * ev.cost)
        return {OptimizationStatus::Converged, "relative cost decrease below tolerance"};
      if (dx.norm() <= params.step_tolerance * (std::sqrt(x_norm2) + params.step_tolerance))
        return {OptimizationStatus::Converged, "step below tolerance"};
      continue;
    }
    lambda *= nu;
    nu *= 2.0;
    if (lambda > params.lm_max_lambda)
    {
      // No decrease even for tiny steps: at a minimum, unless nothing ever solved.
      if (rep.accepted_steps == 0 && !solved)
        return {OptimizationStatus::Diverged, "the damped normal equations never solved"};
      return {OptimizationStatus::Converged, "no further decrease (damping at maximum)"};
    }
  }
  return {};
}
}  // namespace

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
  return evaluate(problem, problem.poses, BarronKernel{2.0, 1.0}, measurementRotations(problem))
      .chi2;
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

std::vector<size_t> switchedOffEdges(const GraphProblem& problem, const GraphOptimizerParams& params)
{
  const std::vector<double> r = robustResiduals(problem);
  std::vector<size_t> off;
  for (size_t n = 0; n < problem.edges.size(); ++n)
    if (problem.edges[n].robust && normalizedBarronWeight(r[n], params.kernel()) < params.switched_off_weight)
      off.push_back(n);
  return off;
}

namespace
{
/** The optimization with the kernel as params give it (KernelSchedule::Fixed). */
OptimizationReport optimizeWithKernel(GraphProblem& problem, const GraphOptimizerParams& params)
{
  mrpt::system::CTicTac timer;
  params.check();
  checkProblem(problem);
  OptimizationReport rep;
  rep.edges = problem.edges.size();
  const std::vector<int> var = variableIndex(problem, rep.components);
  rep.free_nodes = std::count_if(var.begin(), var.end(), [](int v) { return v >= 0; });
  rep.fixed_nodes = problem.poses.size() - rep.free_nodes;

  std::vector<geometry::Pose2> x = problem.poses;
  const std::vector<geometry::SinCos> rz = measurementRotations(problem);
  Evaluation ev = evaluate(problem, x, params.kernel(), rz);
  rep.initial_chi2 = rep.final_chi2 = ev.chi2;
  rep.initial_cost = rep.final_cost = ev.cost;
  rep.active_sq_residuals = ev.active;
  Outcome out;
  if (!std::isfinite(ev.cost))
    out = {OptimizationStatus::Diverged, "initial cost is not finite (a NaN pose or an overflowing information matrix)"};
  else if (rep.free_nodes == 0 || problem.edges.empty())
    out = {OptimizationStatus::NothingToOptimize, "no free pose or no edge"};
  else
    out = levenbergMarquardt(problem, var, params, rz, x, ev, rep);

  if (out.status != OptimizationStatus::Diverged && out.status != OptimizationStatus::NothingToOptimize)
  {
    problem.poses = x;
    rep.final_chi2 = ev.chi2;
    rep.final_cost = ev.cost;
    rep.active_sq_residuals = ev.active;
  }
  rep.status = out.status;
  rep.message = out.why;
  rep.time_s = timer.Tac();
  return rep;
}

/** Graduated non-convexity over the kernel's scale (KernelSchedule::Gnc): stages of
 * optimizeWithKernel with c = kernel_c sqrt(mu), mu from max(1, 2 r_max^2 / kernel_c^2) down
 * to 1 by gnc_factor, each from the last one's poses. */
OptimizationReport optimizeGnc(GraphProblem& problem, const GraphOptimizerParams& params)
{
  mrpt::system::CTicTac timer;
  params.check();
  checkProblem(problem);
  const std::vector<geometry::Pose2> given = problem.poses;
  const std::vector<double> r = robustResiduals(problem);
  const double r_max = r.empty() ? 0.0 : *std::max_element(r.begin(), r.end());
  // Not finite: the first stage reports the divergence.
  double mu = std::isfinite(r_max) ? std::max(1.0, 2 * r_max * r_max / (params.kernel_c * params.kernel_c)) : 1.0;
  GraphOptimizerParams stage = params;
  stage.kernel_schedule = KernelSchedule::Fixed;
  OptimizationReport total;
  for (size_t k = 0;; ++k)
  {
    stage.kernel_c = params.kernel_c * std::sqrt(mu);
    stage.max_iterations = mu > 1 ? std::min(params.max_iterations, params.gnc_stage_iterations) : params.max_iterations;
    const OptimizationReport s = optimizeWithKernel(problem, stage);
    if (k == 0)
    {
      total = s;
      // The first stage starts under its own, wider kernel: the initial cost is the target's.
      total.initial_cost = evaluate(problem, given, params.kernel(), measurementRotations(problem)).cost;
    }
    else
    {
      total.iterations += s.iterations;
      total.accepted_steps += s.accepted_steps;
      total.final_chi2 = s.final_chi2;
      total.final_cost = s.final_cost;
      total.active_sq_residuals = s.active_sq_residuals;
      total.status = s.status;
      total.message = s.message;
    }
    if (s.status == OptimizationStatus::Diverged)
    {
      problem.poses = given;
      total.status = s.status;
      total.message = "stage " + std::to_string(k + 1) + " (c = " + std::to_string(stage.kernel_c) + "): " + s.message;
      break;
    }
    total.stages = k + 1;
    if (s.status == OptimizationStatus::NothingToOptimize || mu <= 1) break;
    mu = std::max(1.0, mu / params.gnc_factor);
  }
  if (total.status == OptimizationStatus::Diverged || total.status == OptimizationStatus::NothingToOptimize)
  {
    total.time_s = timer.Tac();
    return total;
  }
  // The edges the kernel kept are inliers: a last least-squares solve on them alone, so that
  // their noise is not down-weighted (with no outlier this is the least-squares optimum).
  GraphProblem inliers = problem;
  inliers.edges.clear();
  const std::vector<size_t> off = switchedOffEdges(problem, params);
  for (size_t n = 0, k = 0; n < problem.edges.size(); ++n)
  {
    if (k < off.size() && off[k] == n)
      ++k;
    else
      inliers.edges.push_back(problem.edges[n]);
  }
  GraphOptimizerParams l2 = stage;
  l2.kernel_alpha = 2;
  l2.max_iterations = params.max_iterations;
  const OptimizationReport refit = optimizeWithKernel(inliers, l2);
  total.iterations += refit.iterations;
  total.accepted_steps += refit.accepted_steps;
  if (refit.status != OptimizationStatus::Diverged) problem.poses = inliers.poses;
  const Evaluation end = evaluate(problem, problem.poses, params.kernel(), measurementRotations(problem));
  total.final_chi2 = end.chi2;
  total.final_cost = end.cost;
  total.active_sq_residuals = end.active;
  total.message = "graduated non-convexity, " + std::to_string(total.stages) + " stages, then least squares on the " +
                  std::to_string(inliers.edges.size()) + " edges kept: " + total.message;
  total.time_s = timer.Tac();
  return total;
}
}  // namespace

OptimizationReport optimizeGraphProblem(GraphProblem& problem, const GraphOptimizerParams& params)
{
  OptimizationReport rep = params.kernel_schedule == KernelSchedule::Gnc ? optimizeGnc(problem, params)
                                                                          : optimizeWithKernel(problem, params);
  // Which robustified edges the kernel has switched off at the result.
  if (rep.status != OptimizationStatus::NothingToOptimize) rep.switched_off = switchedOffEdges(problem, params);
  return rep;
}

}  // namespace swslam::graph

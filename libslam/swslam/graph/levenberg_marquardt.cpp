#include <swslam/graph/levenberg_marquardt.h>

#include <swslam/graph/normal_equations.h>

#include <mrpt/system/CTicTac.h>

#include <algorithm>
#include <cmath>
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

EdgeCost edgeCost(double r, const GraphProblem::Edge& e, const KindKernels& kernels)
{
  if (!e.robust) return {0.5 * r * r, 1.0};
  const BarronKernel& k = kernels[static_cast<int>(e.kind)];
  return {normalizedBarronRho(r, k), normalizedBarronWeight(r, k)};
}

/** Fills H and g with the IRLS-weighted Gauss-Newton terms at x (eq. 11-13); a decoupled edge
 * (coupled_system.h) adds no block between its two poses. */
void linearize(const GraphProblem& p, const std::vector<geometry::Pose2>& x, const std::vector<int>& var,
               const KindKernels& k, const std::vector<geometry::SinCos>& rz, const CoupledSystem& sys,
               bool exact, NormalEquations& ne)
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
    const Eigen::Matrix3d W = edgeCost(r, e, k).weight * e.information;
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
    if (a >= 0 && b >= 0)
    {
      if (sys.coupled(n)) ne.addOffDiagonal(a, b, Ji.transpose() * W * Jj);
      else if (exact) ne.addOffPattern(a, b, Ji.transpose() * W * Jj);
    }
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


struct Outcome
{
  OptimizationStatus status = OptimizationStatus::MaxIterations;
  std::string why = "reached max_iterations";
};

/** Levenberg-Marquardt with IRLS reweighting at every linearization (eq. 11-13). Updates x
 * and ev (its evaluation) on every accepted step, and the iteration counts of rep. */
Outcome levenbergMarquardt(const GraphProblem& p, const std::vector<int>& var,
                           const GraphOptimizerParams& params, const KindKernels& kernel,
                           const std::vector<geometry::SinCos>& rz, std::vector<geometry::Pose2>& x,
                           Evaluation& ev, OptimizationReport& rep, const SystemUse& use)
{
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(p.edges.size());
  for (const auto& e : p.edges) pairs.emplace_back(var[e.i], var[e.j]);
  CoupledSystem own;
  CoupledSystem& sys = use.shared ? *use.shared : own;
  const bool exact = use.coupling == Coupling::Exact;
  const WeakEdges weak = [&](double weight) { return weakEdges(p, x, kernel, rz, weight); };
  prepareCoupling(sys, use.coupling, static_cast<int>(rep.free_nodes), pairs, weak);

  // Carried over from a solve from nearby poses: there the damping had already fallen, and
  // starting again at lm_initial_lambda damps the graph's slow (long-range) modes, so that
  // least squares after the stages of gnc took 6 steps of linear convergence where 3 do.
  double own_damping = params.lm_initial_lambda;
  double& lambda = use.damping ? *use.damping : own_damping;
  if (!(lambda > 0.0 && lambda <= params.lm_initial_lambda)) lambda = params.lm_initial_lambda;
  double nu = 2.0;
  Eigen::VectorXd dx;
  bool relinearize = true;
  while (rep.iterations < params.max_iterations)
  {
    NormalEquations& ne = sys.equations();
    if (relinearize) linearize(p, x, var, kernel, rz, sys, exact, ne);
    relinearize = false;
    if (ne.gradient().lpNorm<Eigen::Infinity>() < params.gradient_tolerance)
      return {OptimizationStatus::Converged, "gradient below tolerance"};
    ++rep.iterations;
    const bool solved = ne.solveDamped(lambda, dx);
    rep.cg_iterations += static_cast<size_t>(ne.refineIterations());
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
      decoupleAfterStep(sys, use.coupling, p.edges.size(), weak);
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

std::vector<geometry::SinCos> poseRotations(const std::vector<geometry::Pose2>& x)
{
  std::vector<geometry::SinCos> r;
  r.reserve(x.size());
  for (const auto& pose : x) r.push_back(geometry::sinCos(pose.z()));
  return r;
}

std::vector<geometry::SinCos> measurementRotations(const GraphProblem& p)
{
  std::vector<geometry::SinCos> r;
  r.reserve(p.edges.size());
  for (const auto& e : p.edges) r.push_back(geometry::sinCos(e.z.z()));
  return r;
}

Evaluation evaluate(const GraphProblem& p, const std::vector<geometry::Pose2>& x, const KindKernels& k,
                    const std::vector<geometry::SinCos>& rz)
{
  Evaluation ev;
  const std::vector<geometry::SinCos> rx = poseRotations(x);
  for (size_t n = 0; n < p.edges.size(); ++n)
  {
    const auto& e = p.edges[n];
    const Eigen::Vector3d err = geometry::se2Error(x[e.i], x[e.j], e.z, rx[e.i], rz[n]);
    const double r2 = err.dot(e.information * err);
    const EdgeCost c = edgeCost(std::sqrt(r2), e, k);
    ev.cost += c.cost;
    ev.chi2 += r2;
    ev.active += c.weight * r2;
  }
  return ev;
}

std::vector<char> weakEdges(const GraphProblem& p, const std::vector<geometry::Pose2>& x, const KindKernels& k,
                            const std::vector<geometry::SinCos>& rz, double weight)
{
  std::vector<char> weak(p.edges.size(), 0);
  const std::vector<geometry::SinCos> rx = poseRotations(x);
  for (size_t n = 0; n < p.edges.size(); ++n)
  {
    const auto& e = p.edges[n];
    if (!e.robust) continue;
    const Eigen::Vector3d err = geometry::se2Error(x[e.i], x[e.j], e.z, rx[e.i], rz[n]);
    weak[n] = edgeCost(std::sqrt(err.dot(e.information * err)), e, k).weight < weight;
  }
  return weak;
}

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

OptimizationReport optimizeWithKernels(GraphProblem& problem, const GraphOptimizerParams& params,
                                       const KindKernels& kernels, const SystemUse& use)
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
  Evaluation ev = evaluate(problem, x, kernels, rz);
  rep.kernels = kernels;
  rep.initial_chi2 = rep.final_chi2 = ev.chi2;
  rep.initial_cost = rep.final_cost = ev.cost;
  rep.active_sq_residuals = ev.active;
  Outcome out;
  if (!std::isfinite(ev.cost))
    out = {OptimizationStatus::Diverged, "initial cost is not finite (a NaN pose or an overflowing information matrix)"};
  else if (rep.free_nodes == 0 || problem.edges.empty())
    out = {OptimizationStatus::NothingToOptimize, "no free pose or no edge"};
  else
    out = levenbergMarquardt(problem, var, params, kernels, rz, x, ev, rep, use);

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

}  // namespace swslam::graph

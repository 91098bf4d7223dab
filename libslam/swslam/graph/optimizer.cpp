#include <swslam/graph/optimizer.h>

#include <swslam/graph/adaptive_kernel.h>
#include <swslam/graph/coupled_system.h>
#include <swslam/graph/normal_equations.h>
#include <swslam/graph/outlier_decision.h>

#include <mrpt/system/CTicTac.h>

#include <algorithm>
#include <array>
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

EdgeCost edgeCost(double r, const GraphProblem::Edge& e, const KindKernels& kernels)
{
  if (!e.robust) return {0.5 * r * r, 1.0};
  const BarronKernel& k = kernels[static_cast<int>(e.kind)];
  return {normalizedBarronRho(r, k), normalizedBarronWeight(r, k)};
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

/** Per edge, whether its IRLS weight at x is below `weight` (robustified edges only). */
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

/** An edge whose weight is below this is decoupled in the non-convex stages of graduated
 * non-convexity (coupled_system.h). With 0.1 (what the default switched_off_weight calls
 * switched off) the true edges still strained after the convex stage were decoupled too, and
 * 1000 false loops then needed more refits than allowed (0.09 m off the optimum). */
constexpr double kDecoupledWeight = 0.01;
/** Edges are decoupled once at least this share of them would be (each time the pattern
 * changes its symbolic analysis is redone): not for a few false loops, which add little
 * fill-in. */
constexpr double kMinDecoupledShare = 0.01;

/** An exact solve (Coupling::Exact) decouples edges only if every edge coupled fills the
 * factor in beyond this many non-zeros per column, and then those whose weight is below
 * kPreconditionerWeight. On the false-loop benchmark's grid walk (doc/graph-optimization.md)
 * the factor holds about 40 per column with no false loop, 50 with 100 and 130-210 with
 * 1000; the conjugate gradients took 15-25 iterations per solve at weight 0.01, 70-140 at
 * 0.1 (a factor of half the flops) and about 150 with no false loop, where a decoupled true
 * loop still strained from the odometry guess makes them slow. */
constexpr double kDenseFillPerColumn = 100.0;
constexpr double kPreconditionerWeight = 0.1;

/** Which edges an optimization couples in its normal equations (coupled_system.h). */
enum class Coupling
{
  All,  ///< every edge
  /** Those the last solve kept coupled (of the same edges), less the edges whose weight is
   * below kDecoupledWeight, checked at the start and after every accepted step. */
  DecoupleWeak,
  /** As DecoupleWeak, but from every edge coupled (after an Exact solve, whose decoupled
   * edges were weak at its own start, before its steps). */
  DecoupleWeakAfresh,
  /** Every edge, unless that factor is dense (kDenseFillPerColumn); then the edges weak at
   * the start (kPreconditionerWeight) are decoupled for the whole solve, but their blocks
   * are still in it, off the factor's pattern (conjugate gradients preconditioned by the
   * factor): the step is the coupled one, at the cost of a sparse factor. */
  Exact,
};

/** How an optimization keeps its normal equations. */
struct SystemUse
{
  CoupledSystem* shared = nullptr;  ///< kept across solves (nullptr: one of its own)
  Coupling coupling = Coupling::All;
  /** The damping, carried from one solve to the next that goes on from its poses (nullptr:
   * lm_initial_lambda). In: the damping to start with, if positive, at most
   * lm_initial_lambda; out: the damping at the end. */
  double* damping = nullptr;
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
  const size_t min_decoupled =
      std::max<size_t>(1, static_cast<size_t>(kMinDecoupledShare * static_cast<double>(p.edges.size())));
  const int free_blocks = static_cast<int>(rep.free_nodes);
  const bool exact = use.coupling == Coupling::Exact;
  const bool decouple = use.coupling == Coupling::DecoupleWeak || use.coupling == Coupling::DecoupleWeakAfresh;
  if (exact && NormalEquations::fillPerColumnOf(free_blocks, pairs) > kDenseFillPerColumn)
    sys.prepareDecoupled(free_blocks, pairs, weakEdges(p, x, kernel, rz, kPreconditionerWeight), min_decoupled);
  else if (use.coupling == Coupling::DecoupleWeakAfresh)
    sys.prepareDecoupled(free_blocks, pairs, weakEdges(p, x, kernel, rz, kDecoupledWeight), min_decoupled);
  else
  {
    sys.prepare(free_blocks, pairs, decouple);
    if (decouple) sys.decouple(weakEdges(p, x, kernel, rz, kDecoupledWeight), min_decoupled);
  }

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
      if (decouple) sys.decouple(weakEdges(p, x, kernel, rz, kDecoupledWeight), min_decoupled);
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

namespace
{
/** The optimization with the given kernel per edge kind, from the problem's poses. */
OptimizationReport optimizeWithKernels(GraphProblem& problem, const GraphOptimizerParams& params,
                                       const KindKernels& kernels, const SystemUse& use = {})
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

/** Graduated non-convexity (KernelSchedule::Gnc, ::Adaptive): stages of a few iterations
 * each, the shape bounded below by 1, 1 - gnc_alpha_step, ... (convex at first), each stage
 * from the last one's poses; then least squares on the edges the last stage's kernel kept,
 * so that their noise is not down-weighted (with no outlier this is the least-squares
 * optimum). */
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
  const double alpha_end = adaptive ? params.adaptive_alpha_min : params.kernel_alpha;
  const std::vector<geometry::Pose2> given = problem.poses;
  GraphOptimizerParams stage = params;
  stage.max_iterations = std::min(params.max_iterations, params.gnc_stage_iterations);
  // Without a fixed target (adaptive), no stage ends the graduation early.
  const KindKernels target = uniformKernels(params.kernel());
  CoupledSystem sys;  // one pattern for every stage (their edges are the same)
  double damping = 0;  // carried from stage to stage and into the least squares after them
  OptimizationReport total;
  KindKernels kernels, previous;
  for (size_t k = 0;; ++k)
  {
    // The bound of this stage's shape: 1 (convex), then lower by gnc_alpha_step each stage;
    // the last one is alpha_end (a shape below kLowestGraduatedAlpha is reached at once).
    double floor = 1.0 - static_cast<double>(k) * params.gnc_alpha_step;
    const bool last = floor <= alpha_end || floor < kLowestGraduatedAlpha;
    if (last) floor = alpha_end;
    bool limited = !last;  // gnc: the stages go on down to the target
    kernels = adaptive ? estimateKernels(problem, params, *shapes, floor, 1.0, false, limited)
                       : uniformKernels({floor, params.kernel_c});
    // The convex first stage solves exactly, every edge coupled: from the given poses the
    // true loops are as far off as the false ones (drift), and decoupling them there
    // spoiled the stage (with no false loop, 145 edges decoupled after its first step, and
    // 69 true edges ended switched off by the target kernel instead of none). Where that
    // factor is dense (a thousand long false loops), the weak edges are solved by conjugate
    // gradients off the factor's pattern instead (Coupling::Exact). The next stage starts
    // with every edge coupled again, then decouples those weak at its own poses. The
    // adaptive kernel decouples nothing: with it, 100 random false loops ended 0.027 m off
    // with a true edge switched off, against 0.0004 m.
    const Coupling coupling = adaptive ? Coupling::All
                              : k == 0 ? Coupling::Exact
                              : k == 1 ? Coupling::DecoupleWeakAfresh
                                       : Coupling::DecoupleWeak;
    const OptimizationReport s = optimizeWithKernels(problem, stage, kernels, {&sys, coupling, &damping});
    if (k == 0)
    {
      total = s;
      total.initial_cost = evaluate(problem, given, kernels, measurementRotations(problem)).cost;
    }
    else
    {
      total.iterations += s.iterations;
      total.accepted_steps += s.accepted_steps;
      total.cg_iterations += s.cg_iterations;
      total.status = s.status;
      total.message = s.message;
    }
    total.stages = k + 1;
    if (s.status == OptimizationStatus::Diverged)
    {
      problem.poses = given;
      total.message = "stage " + std::to_string(k + 1) + ": " + s.message;
      total.time_s = timer.Tac();
      return total;
    }
    if (s.status == OptimizationStatus::NothingToOptimize)
    {
      total.time_s = timer.Tac();
      return total;
    }
    // Done at the last bound, or (adaptive) when the bound no longer holds a shape back and
    // the estimate has settled: from a poor guess every residual is large, so the first
    // scales are wide and the shapes near 2 until the poses come near the inliers.
    if (last || (!limited && k > 0 && settled(previous, kernels, params.adaptive_alpha_step))) break;
    // gnc: little outlier evidence, at most kFewOutliers of the edges that the target kernel
    // would switch off at these poses: go straight to least squares on the others. With none,
    // the lower shapes would weigh every edge about as least squares does; with a few, the
    // graph's poses are already near the inliers' optimum, and the refit rounds take back an
    // edge that agrees with it and take out one the graph had absorbed.
    if (!adaptive && problem.edges.size() >= kMinEdgesForEarlyEnd && static_cast<double>(switchedOffEdges(problem, target, params.switched_off_weight).size()) <=
                         kFewOutliers * static_cast<double>(problem.edges.size()))
    {
      kernels = target;
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
  {
    problem.poses = given;
    total.message = "the least-squares solve on the kept edges: " + refit.message;
    total.time_s = timer.Tac();
    return total;
  }
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
}  // namespace

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

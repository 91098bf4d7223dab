#pragma once
// A pose-graph problem given as plain values (poses, which of them are held fixed, and
// relative-pose edges with information matrices) and its optimization by kernel schedule
// (optimizeGraphProblem): the fixed kernel by Levenberg-Marquardt with iteratively reweighted
// least squares (paper eq. 11-13; levenberg_marquardt.h), graduated non-convexity and the
// adaptive kernel (graduated.h), truncated least squares (outlier_decision.h).

#include <swslam/geometry/se2_error.h>
#include <swslam/graph/optimizer_params.h>

#include <array>
#include <string>
#include <vector>

namespace swslam::graph
{
struct GraphProblem
{
  struct Edge
  {
    int i = 0, j = 0;              ///< indices into poses
    geometry::Pose2 z = geometry::Pose2::Zero();       ///< pose of j seen from i
    Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
    bool robust = false;           ///< weighted by the Barron kernel
    EdgeKind kind = EdgeKind::Loop;  ///< which kernel weighs it (adaptive: one per kind)
  };
  std::vector<geometry::Pose2> poses;
  std::vector<char> fixed;  ///< per pose; a connected component with none fixed is held at its first pose
  std::vector<Edge> edges;
};

enum class OptimizationStatus
{
  Converged,          ///< a tolerance was met (or the damping grew past lm_max_lambda)
  MaxIterations,      ///< stopped after max_iterations linear solves
  NothingToOptimize,  ///< no free pose or no edge: poses unchanged
  Diverged            ///< non-finite cost or failed solve: poses left as they were
};
const char* statusName(OptimizationStatus s);

/** A Barron kernel per edge kind (indexed by EdgeKind). */
using KindKernels = std::array<BarronKernel, kEdgeKindCount>;
KindKernels uniformKernels(const BarronKernel& k);

struct OptimizationReport
{
  OptimizationStatus status = OptimizationStatus::NothingToOptimize;
  size_t iterations = 0;        ///< linear solves (accepted and rejected LM steps)
  size_t accepted_steps = 0;
  double initial_chi2 = 0;      ///< sum of e^T Omega e over the problem's edges
  double final_chi2 = 0;
  double initial_cost = 0;      ///< robust cost: sum of c^2 rho(r) (robust) or r^2/2 (others)
  double final_cost = 0;
  double active_sq_residuals = 0;  ///< sum of w r^2 at the result (eq. 11; paper Fig. 7)
  double time_s = 0;
  size_t free_nodes = 0, fixed_nodes = 0, edges = 0;
  /** Connected components of the poses; each one without a fixed pose is held at its first
   * pose (a graph that falls apart into pieces has nothing to tie them together). */
  size_t components = 0;
  size_t stages = 1;            ///< gnc, adaptive: kernels optimized in turn
  /** Conjugate-gradient iterations of the solves whose factor left weak edges out (gnc's
   * first stage on a dense graph; 0: every solve was direct). */
  size_t cg_iterations = 0;
  /** The kernel per edge kind at the end (adaptive: as estimated from the residuals). */
  KindKernels kernels{};
  std::vector<size_t> switched_off;  ///< robustified edges whose final weight is below switched_off_weight
  /** A whole graph's optimization started from LAGO's poses, not the guess (initialization.h). */
  bool lago_start = false;
  /** Tls: the proposal whose inliers won (outlier_decision.h). */
  std::string start;
  std::string message;          ///< why it stopped, in words
};

/** chi2 = sum over edges of e^T Omega e at the problem's poses. */
double graphChi2(const GraphProblem& problem);

/** The robust cost sum of c^2 rho(r) (robustified edges, under their kind's kernel) and r^2 / 2
 * (the others) at the problem's poses: what the optimizer minimizes. */
double robustCost(const GraphProblem& problem, const KindKernels& kernels);

/** Throws std::invalid_argument if an edge names a pose out of range or joins a pose to
 * itself, or the per-pose vectors differ in size. */
void checkProblem(const GraphProblem& problem);

/** sqrt(e^T Omega e) of each robustified edge at the problem's poses (0 for the others). */
std::vector<double> robustResiduals(const GraphProblem& problem);

/** The robustified edges (indices into problem.edges, increasing) whose weight under their
 * kind's kernel is below `weight` at the problem's poses. */
std::vector<size_t> switchedOffEdges(const GraphProblem& problem, const KindKernels& kernels, double weight);
/** The same with params' kernel for every kind and params.switched_off_weight. */
std::vector<size_t> switchedOffEdges(const GraphProblem& problem, const GraphOptimizerParams& params);

/** Optimizes problem.poses in place, with the kernel schedule of params (fixed, graduated
 * non-convexity or adaptive), and reports the robustified edges the kernel switched off. On Diverged the
 * poses are left exactly as given. */
OptimizationReport optimizeGraphProblem(GraphProblem& problem, const GraphOptimizerParams& params);

}  // namespace swslam::graph

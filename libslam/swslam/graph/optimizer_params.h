#pragma once
// Parameters of the robust pose-graph optimizer, section [graph_optimizer].

#include <swslam/graph/edge_kind.h>
#include <swslam/graph/robust_kernel.h>

#include <swslam/common/param_table.h>

#include <mrpt/core/bits_math.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>

namespace swslam::graph
{
/** How the kernel is applied (doc/graph-optimization.md):
 * - Fixed: as it is from the start (the paper);
 * - Gnc: graduated non-convexity along Barron's family (Barron, CVPR 2019, sec. 3; Yang et
 *   al., RA-L 2020): the shape starts convex (alpha = 1) and falls by gnc_alpha_step each
 *   stage to kernel_alpha, each stage started from the last one's result; then least squares
 *   on the edges the kernel kept;
 * - Adaptive: as Gnc, but each stage's shape per edge kind is estimated from the residuals
 *   (Chebrolu et al., RA-L 2021): the shape that fits them best, held within the stage's
 *   bounds; the kernels at the result also take the scale kernel_c times a robust residual
 *   scale;
 * - Tls: truncated least squares for a whole graph, its robustified edges decided together
 *   (outlier_decision.h): the lowest truncated cost among proposed inlier sets, each refined
 *   by least squares on the edges within outlier_gate. */
enum class KernelSchedule
{
  Fixed,
  Gnc,
  Adaptive,
  Tls
};
const char* kernelScheduleName(KernelSchedule s);
/** "fixed", "gnc", "adaptive" or "tls"; nothing for another name. */
std::optional<KernelSchedule> kernelScheduleFromName(const std::string& name);

/** Section [graph_optimizer]: declared in table() (optimizer_params.cpp). */
struct GraphOptimizerParams
{
  // Barron kernel (paper eq. 14) on r = sqrt(e^T Omega e), so c is in standard deviations.
  double kernel_alpha = 0.0;  ///< [-inf, 2]: 2 L2, 0 Cauchy, -2 Geman-McClure, -inf Welsch
  double kernel_c = 3.0;      ///< residual (Mahalanobis) where down-weighting begins
  KernelSchedule kernel_schedule = KernelSchedule::Fixed;  ///< ini: fixed | gnc | adaptive
  /** gnc, adaptive: the shape's bound falls by this each stage, from 1 (convex) down to
   * kernel_alpha (gnc) or adaptive_alpha_min (adaptive). */
  double gnc_alpha_step = 1.0;
  /** gnc, adaptive: LM iterations per stage (each stage only brings the poses near the next,
   * less convex, problem's basin); the least-squares solve on the edges kept gets
   * max_iterations. */
  size_t gnc_stage_iterations = 3;
  /** adaptive: the shapes estimated lie in [adaptive_alpha_min, adaptive_alpha_max], on a grid
   * of adaptive_alpha_step. */
  double adaptive_alpha_min = -10.0;
  double adaptive_alpha_max = 0.0;
  double adaptive_alpha_step = 0.1;
  /** adaptive: the density of the residuals over the scale is truncated at this many scales
   * (so that it can be normalized for every shape). */
  double adaptive_truncation = 10.0;
  /** A robustified edge whose final weight (1 for an inlier) is below this is reported as
   * switched off (OptimizationReport::switched_off). */
  double switched_off_weight = 0.1;
  /** tls: a robustified loop is an outlier beyond this residual r = sqrt(e^T Omega e). A true
   * edge whose noise is as its information says lies beyond 5 with probability 1.2e-5
   * (chi-square, three degrees of freedom); at 4.03 (0.999) the decision switched off one true
   * loop in a thousand with the false ones. */
  double outlier_gate = 5.0;
  /** tls: the same for an edge of the chain (consecutive, dense-neighbour, odometry prior):
   * larger, since switching one off costs its square, and with the loops' gate a graph could
   * break its chain to take in a group of false loops more cheaply than keep it (truncated.h). */
  double outlier_gate_chain = 12.0;

  // Which edge kinds are robustified (paper: consecutive constraints; loops too, see issue 5).
  bool robust_consecutive = true;
  bool robust_dense_neighbour = false;
  bool robust_loop = true;
  bool robust_odometry_prior = false;

  size_t window_size = 30;  ///< newest nodes optimized per sliding-window update
  /** A full optimization after a loop waits until this many nodes have passed since the last
   * one (loops accepted meanwhile get the window); 1: after every node that closes a loop. */
  size_t full_optimization_interval = 5;
  /** Only a loop that differs from the graph's relative pose of its nodes by more than this
   * [m] or full_optimization_loop_theta [rad] asks for a full optimization; the window takes
   * the others (0 and 0: every loop, the paper's rule). */
  double full_optimization_loop_xy = 0.05;
  double full_optimization_loop_theta = mrpt::DEG2RAD(0.5);

  /** Revisits (doc/graph-optimization.md, Revisits): a new node that a loop ties to a node of
   * an earlier pass within node_area_radius, where at least this many nodes of earlier passes
   * lie within that radius, is merged into it (PoseGraph::merge) once the loop agrees with the
   * graph (loopCorrectsGraph is false after the window's optimization); 0: every node kept. */
  size_t max_nodes_per_area = 1;
  double node_area_radius = 1.0;  ///< [m]

  size_t max_iterations = 100;        ///< LM iterations (paper: 100)
  double lm_initial_lambda = 1e-4;    ///< damping relative to diag(H) at the first iteration
  double lm_max_lambda = 1e12;        ///< give up (converged or stuck) beyond this damping
  double relative_cost_tolerance = 1e-6;  ///< stop when the cost decreases by less than this
  double step_tolerance = 1e-10;      ///< stop when |dx| < tol * (|x| + tol)
  double gradient_tolerance = 1e-12;  ///< stop when max |gradient| is below this

  BarronKernel kernel() const { return {kernel_alpha, kernel_c}; }
  bool isRobust(EdgeKind kind) const;

  /** Throws std::invalid_argument naming the first out-of-range parameter. */
  void check() const;

  static const common::ParamTable<GraphOptimizerParams>& table();
};

}  // namespace swslam::graph

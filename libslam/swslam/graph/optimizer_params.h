#pragma once
// Parameters of the robust pose-graph optimizer, section [graph_optimizer].

#include <swslam/graph/edge_kind.h>
#include <swslam/graph/robust_kernel.h>

#include <mrpt/config/CLoadableOptions.h>

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>

namespace swslam::graph
{
/** How the kernel is applied: as it is from the start (the paper), or by graduated
 * non-convexity (Yang et al., RA-L 2020): the scale starts where every residual of the
 * initial guess is an inlier (a convex, least-squares-like problem) and shrinks stage by
 * stage to kernel_c, each stage started from the last one's result. */
enum class KernelSchedule
{
  Fixed,
  Gnc
};
const char* kernelScheduleName(KernelSchedule s);
/** "fixed" or "gnc"; nothing for another name. */
std::optional<KernelSchedule> kernelScheduleFromName(const std::string& name);

struct GraphOptimizerParams : public mrpt::config::CLoadableOptions
{
  // Barron kernel (paper eq. 14) on r = sqrt(e^T Omega e), so c is in standard deviations.
  double kernel_alpha = 0.0;  ///< [-inf, 2]: 2 L2, 0 Cauchy, -2 Geman-McClure, -inf Welsch
  double kernel_c = 3.0;      ///< residual (Mahalanobis) where down-weighting begins
  KernelSchedule kernel_schedule = KernelSchedule::Fixed;  ///< ini: kernel_schedule = fixed | gnc
  /** GNC: mu, the square of the scale's multiple of kernel_c, starts at
   * max(1, 2 r_max^2 / kernel_c^2) (r_max: the largest robustified residual of the initial
   * guess) and is divided by this each stage down to 1. */
  double gnc_factor = 2.0;
  /** GNC: LM iterations per stage before the last (each stage only needs to bring the poses
   * near the next, slightly less convex, problem's basin); the last stage and the least-squares
   * solve on the edges kept get max_iterations. */
  size_t gnc_stage_iterations = 3;
  /** A robustified edge whose final weight (1 for an inlier) is below this is reported as
   * switched off (OptimizationReport::switched_off). */
  double switched_off_weight = 0.1;

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
  double full_optimization_loop_theta = 0.5 * M_PI / 180;

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

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

}  // namespace swslam::graph

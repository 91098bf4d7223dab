#include <swslam/graph/optimizer_params.h>


#include <cmath>
#include <stdexcept>
#include <string>

namespace swslam::graph
{
bool GraphOptimizerParams::isRobust(EdgeKind kind) const
{
  switch (kind)
  {
    case EdgeKind::Consecutive: return robust_consecutive;
    case EdgeKind::DenseNeighbour: return robust_dense_neighbour;
    case EdgeKind::Loop: return robust_loop;
    case EdgeKind::OdometryPrior: return robust_odometry_prior;
  }
  return false;
}

void GraphOptimizerParams::check() const { table().check(*this); }

const char* kernelScheduleName(KernelSchedule s)
{
  switch (s)
  {
    case KernelSchedule::Fixed: return "fixed";
    case KernelSchedule::Gnc: return "gnc";
    case KernelSchedule::Adaptive: return "adaptive";
    case KernelSchedule::Tls: return "tls";
  }
  return "?";
}

std::optional<KernelSchedule> kernelScheduleFromName(const std::string& name)
{
  for (const KernelSchedule s : {KernelSchedule::Fixed, KernelSchedule::Gnc, KernelSchedule::Adaptive, KernelSchedule::Tls})
    if (name == kernelScheduleName(s)) return s;
  return std::nullopt;
}

const common::ParamTable<GraphOptimizerParams>& GraphOptimizerParams::table()
{
  using P = GraphOptimizerParams;
  using common::Tier;
  using common::above, common::atLeast, common::between;
  static const auto t =
      common::ParamTable<P>("graph_optimizer",
                            "Robust pose-graph optimization (paper sec. III): LM with IRLS and Barron's kernel.")
          .integer("window_size", &P::window_size, "", atLeast(2), "newest nodes optimized whenever a node is added",
                   Tier::User)
          .real("kernel_alpha", &P::kernel_alpha, "", common::Range{-INFINITY, 2, false, false},
                "Barron kernel shape: 2 L2, 1 L1-like, 0 Cauchy, -2 Geman-McClure, -inf Welsch")
          .real("kernel_c", &P::kernel_c, "", above(0), "kernel scale, in standard deviations of r = sqrt(e' Omega e)")
          .choice("kernel_schedule", &P::kernel_schedule,
                  {{"fixed", KernelSchedule::Fixed}, {"gnc", KernelSchedule::Gnc}, {"adaptive", KernelSchedule::Adaptive}, {"tls", KernelSchedule::Tls}},
                  "fixed: the kernel from the start; gnc: graduated from alpha 1 down; adaptive: shapes estimated per edge kind; tls: a whole graph's outliers decided together")
          .real("gnc_alpha_step", &P::gnc_alpha_step, "", between(0.05, 10), "gnc, adaptive: the shape's bound falls by this each stage")
          .integer("gnc_stage_iterations", &P::gnc_stage_iterations, "", atLeast(1), "gnc, adaptive: LM iterations per stage")
          .real("adaptive_alpha_min", &P::adaptive_alpha_min, "", between(-100, 2), "adaptive: the lowest shape estimated...")
          .real("adaptive_alpha_max", &P::adaptive_alpha_max, "", between(-100, 2), "...the highest...")
          .real("adaptive_alpha_step", &P::adaptive_alpha_step, "", between(0.01, 10), "...on a grid of this step")
          .real("adaptive_truncation", &P::adaptive_truncation, "", common::aboveUpTo(1, 1000),
                "adaptive: the residuals' density is truncated at this many scales")
          .real("switched_off_weight", &P::switched_off_weight, "", common::Range{0, 1, false, true},
                "a robustified edge whose final weight is below this is reported as switched off")
          .real("outlier_gate", &P::outlier_gate, "", above(0),
                "tls: a loop beyond this residual (standard deviations) is an outlier...")
          .real("outlier_gate_chain", &P::outlier_gate_chain, "", above(0), "...and an edge of the odometry chain beyond this")
          .flag("robust_consecutive", &P::robust_consecutive, "robustify consecutive edges (the paper's choice)")
          .flag("robust_dense_neighbour", &P::robust_dense_neighbour, "robustify dense-neighbour edges")
          .flag("robust_loop", &P::robust_loop, "robustify loop-closure edges")
          .flag("robust_odometry_prior", &P::robust_odometry_prior, "robustify odometry-prior edges")
          .integer("full_optimization_interval", &P::full_optimization_interval, "", atLeast(1),
                   "after a loop the whole graph is optimized at most once per this many nodes")
          .real("full_optimization_loop_xy", &P::full_optimization_loop_xy, "m", atLeast(0),
                "only a loop off the graph by more than this...")
          .angle("full_optimization_loop_theta_DEG", &P::full_optimization_loop_theta, between(0, 180),
                 "...or this asks for a full optimization (0 and 0: every loop, the paper's rule)")
          .integer("max_nodes_per_area", &P::max_nodes_per_area, "", atLeast(0),
                   "revisits: a node whose loop agrees with the graph is merged into an earlier one once this "
                   "many earlier nodes lie within node_area_radius (0: every node is kept)",
                   common::Tier::User)
          .real("node_area_radius", &P::node_area_radius, "m", above(0), "the area of max_nodes_per_area")
          .integer("max_iterations", &P::max_iterations, "", atLeast(1), "Levenberg-Marquardt iterations at most (paper: 100)")
          .real("lm_initial_lambda", &P::lm_initial_lambda, "", above(0), "initial damping, relative to diag(H)")
          .real("lm_max_lambda", &P::lm_max_lambda, "", above(0), "stop when the damping exceeds this")
          .real("relative_cost_tolerance", &P::relative_cost_tolerance, "", above(0),
                "stop when the cost decreases by less than this fraction")
          .real("step_tolerance", &P::step_tolerance, "", above(0), "stop when |dx| < tol (|x| + tol)")
          .real("gradient_tolerance", &P::gradient_tolerance, "", above(0), "stop when the largest gradient entry is below this")
          .rule([](const P& p) { return p.adaptive_alpha_min <= p.adaptive_alpha_max; },
                "adaptive_alpha_min must not exceed adaptive_alpha_max");
  return t;
}

}  // namespace swslam::graph

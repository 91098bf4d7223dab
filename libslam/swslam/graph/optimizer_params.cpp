#include <swslam/graph/optimizer_params.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/core/bits_math.h>

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

void GraphOptimizerParams::check() const
{
  checkKernel(kernel());
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw std::invalid_argument(std::string("graph_optimizer: ") + name +
                                  " must be finite and > 0, got " + std::to_string(v));
  };
  positive(lm_initial_lambda, "lm_initial_lambda");
  positive(lm_max_lambda, "lm_max_lambda");
  positive(relative_cost_tolerance, "relative_cost_tolerance");
  positive(step_tolerance, "step_tolerance");
  positive(gradient_tolerance, "gradient_tolerance");
  if (window_size < 2) throw std::invalid_argument("graph_optimizer: window_size must be >= 2");
  if (full_optimization_interval < 1)
    throw std::invalid_argument("graph_optimizer: full_optimization_interval must be >= 1");
  if (!(full_optimization_loop_xy >= 0) || !std::isfinite(full_optimization_loop_xy))
    throw std::invalid_argument("graph_optimizer: full_optimization_loop_xy must be finite and >= 0");
  if (!(full_optimization_loop_theta >= 0) || full_optimization_loop_theta > M_PI)
    throw std::invalid_argument(
        "graph_optimizer: full_optimization_loop_theta_DEG must be in [0, 180]");
  if (max_iterations < 1)
    throw std::invalid_argument("graph_optimizer: max_iterations must be >= 1");
  if (gnc_stage_iterations < 1)
    throw std::invalid_argument("graph_optimizer: gnc_stage_iterations must be >= 1");
  if (!(gnc_alpha_step >= 0.05 && gnc_alpha_step <= 10))
    throw std::invalid_argument("graph_optimizer: gnc_alpha_step must be in [0.05, 10]");
  if (!(adaptive_alpha_min >= -100 && adaptive_alpha_min <= adaptive_alpha_max && adaptive_alpha_max <= 2))
    throw std::invalid_argument("graph_optimizer: adaptive_alpha_min and adaptive_alpha_max must satisfy -100 <= min <= max <= 2");
  if (!(adaptive_alpha_step >= 0.01 && adaptive_alpha_step <= 10))
    throw std::invalid_argument("graph_optimizer: adaptive_alpha_step must be in [0.01, 10]");
  if (!(adaptive_truncation > 1 && adaptive_truncation <= 1000))
    throw std::invalid_argument("graph_optimizer: adaptive_truncation must be in (1, 1000]");
  if (!(switched_off_weight >= 0 && switched_off_weight < 1))
    throw std::invalid_argument("graph_optimizer: switched_off_weight must be in [0, 1)");
}

const char* kernelScheduleName(KernelSchedule s)
{
  switch (s)
  {
    case KernelSchedule::Fixed: return "fixed";
    case KernelSchedule::Gnc: return "gnc";
    case KernelSchedule::Adaptive: return "adaptive";
  }
  return "?";
}

std::optional<KernelSchedule> kernelScheduleFromName(const std::string& name)
{
  for (const KernelSchedule s : {KernelSchedule::Fixed, KernelSchedule::Gnc, KernelSchedule::Adaptive})
    if (name == kernelScheduleName(s)) return s;
  return std::nullopt;
}

void GraphOptimizerParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                              const std::string& s)
{
  MRPT_LOAD_CONFIG_VAR(kernel_alpha, double, c, s);
  MRPT_LOAD_CONFIG_VAR(kernel_c, double, c, s);
  const std::string schedule = c.read_string(s, "kernel_schedule", kernelScheduleName(kernel_schedule));
  const auto parsed = kernelScheduleFromName(schedule);
  if (!parsed) throw std::invalid_argument("graph_optimizer: kernel_schedule '" + schedule + "' is not fixed, gnc or adaptive");
  kernel_schedule = *parsed;
  MRPT_LOAD_CONFIG_VAR(gnc_alpha_step, double, c, s);
  gnc_stage_iterations = c.read_uint64_t(s, "gnc_stage_iterations", gnc_stage_iterations);
  MRPT_LOAD_CONFIG_VAR(adaptive_alpha_min, double, c, s);
  MRPT_LOAD_CONFIG_VAR(adaptive_alpha_max, double, c, s);
  MRPT_LOAD_CONFIG_VAR(adaptive_alpha_step, double, c, s);
  MRPT_LOAD_CONFIG_VAR(adaptive_truncation, double, c, s);
  MRPT_LOAD_CONFIG_VAR(switched_off_weight, double, c, s);
  MRPT_LOAD_CONFIG_VAR(robust_consecutive, bool, c, s);
  MRPT_LOAD_CONFIG_VAR(robust_dense_neighbour, bool, c, s);
  MRPT_LOAD_CONFIG_VAR(robust_loop, bool, c, s);
  MRPT_LOAD_CONFIG_VAR(robust_odometry_prior, bool, c, s);
  window_size = c.read_uint64_t(s, "window_size", window_size);
  full_optimization_interval =
      c.read_uint64_t(s, "full_optimization_interval", full_optimization_interval);
  MRPT_LOAD_CONFIG_VAR(full_optimization_loop_xy, double, c, s);
  full_optimization_loop_theta = mrpt::DEG2RAD(c.read_double(
      s, "full_optimization_loop_theta_DEG", mrpt::RAD2DEG(full_optimization_loop_theta)));
  max_iterations = c.read_uint64_t(s, "max_iterations", max_iterations);
  MRPT_LOAD_CONFIG_VAR(lm_initial_lambda, double, c, s);
  MRPT_LOAD_CONFIG_VAR(lm_max_lambda, double, c, s);
  MRPT_LOAD_CONFIG_VAR(relative_cost_tolerance, double, c, s);
  MRPT_LOAD_CONFIG_VAR(step_tolerance, double, c, s);
  MRPT_LOAD_CONFIG_VAR(gradient_tolerance, double, c, s);
  check();
}

void GraphOptimizerParams::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                            const std::string& s) const
{
  c.write(s, "kernel_alpha", kernel_alpha, -1, -1,
          "Barron kernel shape in [-inf, 2]: 2 L2, 1 L1-like, 0 Cauchy, -2 Geman-McClure, -inf Welsch");
  c.write(s, "kernel_c", kernel_c, -1, -1, "kernel scale, in standard deviations of the residual");
  c.write(s, "kernel_schedule", std::string(kernelScheduleName(kernel_schedule)), -1, -1,
          "fixed: the kernel from the start; gnc: graduated non-convexity from alpha 1 down to kernel_alpha; adaptive: as gnc, each stage's shape per edge kind estimated from the residuals, the final kernels' scale too");
  c.write(s, "gnc_alpha_step", gnc_alpha_step, -1, -1, "gnc, adaptive: the shape's bound falls by this each stage");
  c.write(s, "gnc_stage_iterations", gnc_stage_iterations, -1, -1, "gnc, adaptive: LM iterations per stage");
  c.write(s, "adaptive_alpha_min", adaptive_alpha_min, -1, -1, "adaptive: the lowest shape estimated");
  c.write(s, "adaptive_alpha_max", adaptive_alpha_max, -1, -1, "adaptive: the highest shape estimated");
  c.write(s, "adaptive_alpha_step", adaptive_alpha_step, -1, -1, "adaptive: grid step of the shape estimate");
  c.write(s, "adaptive_truncation", adaptive_truncation, -1, -1,
          "adaptive: the residual density is truncated at this many scales");
  c.write(s, "switched_off_weight", switched_off_weight, -1, -1,
          "a robustified edge whose final weight is below this is reported as switched off");
  c.write(s, "robust_consecutive", robust_consecutive, -1, -1, "robustify consecutive edges");
  c.write(s, "robust_dense_neighbour", robust_dense_neighbour, -1, -1,
          "robustify dense-neighbour edges");
  c.write(s, "robust_loop", robust_loop, -1, -1, "robustify loop-closure edges");
  c.write(s, "robust_odometry_prior", robust_odometry_prior, -1, -1,
          "robustify odometry-prior edges");
  c.write(s, "window_size", static_cast<uint64_t>(window_size), -1, -1,
          "newest nodes optimized per sliding-window update");
  c.write(s, "full_optimization_interval", static_cast<uint64_t>(full_optimization_interval), -1,
          -1, "nodes from one full optimization after loops to the next at least");
  c.write(s, "full_optimization_loop_xy", full_optimization_loop_xy, -1, -1,
          "[m] only a loop this far from the graph's relative pose asks for a full optimization...");
  c.write(s, "full_optimization_loop_theta_DEG", mrpt::RAD2DEG(full_optimization_loop_theta), -1,
          -1, "[deg] ...or turned this much from it");
  c.write(s, "max_iterations", static_cast<uint64_t>(max_iterations), -1, -1,
          "Levenberg-Marquardt iterations at most");
  c.write(s, "lm_initial_lambda", lm_initial_lambda, -1, -1, "initial damping, relative to diag(H)");
  c.write(s, "lm_max_lambda", lm_max_lambda, -1, -1, "stop when the damping exceeds this");
  c.write(s, "relative_cost_tolerance", relative_cost_tolerance, -1, -1,
          "stop when the relative cost decrease is below this");
  c.write(s, "step_tolerance", step_tolerance, -1, -1, "stop when |dx| < tol (|x| + tol)");
  c.write(s, "gradient_tolerance", gradient_tolerance, -1, -1,
          "stop when the largest gradient entry is below this");
}

}  // namespace swslam::graph

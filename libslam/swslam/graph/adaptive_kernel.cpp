#include <swslam/graph/adaptive_kernel.h>

#include <swslam/graph/robust_kernel.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace swslam::graph
{
double barronPartition(double alpha, double tau, int intervals)
{
  // The density is even: twice the integral over [0, tau].
  const int n = intervals + intervals % 2;
  const double h = tau / n;
  const BarronKernel k{alpha, 1.0};
  double sum = 0;
  for (int i = 0; i <= n; ++i)
  {
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += w * std::exp(-barronRho(i * h, k));
  }
  return 2.0 * sum * h / 3.0;
}

ShapeEstimator::ShapeEstimator(double alpha_min, double alpha_max, double step, double tau) : tau_(tau)
{
  if (!std::isfinite(alpha_min) || !(alpha_min <= alpha_max) || !(alpha_max <= 2.0) || !(step > 0) || !(tau > 0) ||
      !std::isfinite(tau))
    throw std::invalid_argument("adaptive kernel: needs finite alpha_min <= alpha_max <= 2, step > 0 and tau > 0");
  // From alpha_max down, so that alpha_max itself is on the grid.
  for (size_t k = 0; alpha_max - static_cast<double>(k) * step > alpha_min - 1e-9; ++k)
  {
    alphas_.push_back(alpha_max - static_cast<double>(k) * step);
    log_partition_.push_back(std::log(barronPartition(alphas_.back(), tau)));
  }
}

ShapeEstimate ShapeEstimator::estimate(const std::vector<double>& residuals, double c) const
{
  ShapeEstimate best{alphas_.front(), 0.0};
  if (residuals.empty()) return best;
  const double n = static_cast<double>(residuals.size());
  for (size_t k = 0; k < alphas_.size(); ++k)
  {
    const BarronKernel kernel{alphas_[k], 1.0};
    double nll = 0;
    for (const double r : residuals) nll += barronRho(std::min(r / c, tau_), kernel);
    nll = nll / n + log_partition_[k];
    if (k == 0 || nll < best.negative_log_likelihood) best = {alphas_[k], nll};
  }
  return best;
}

const ShapeEstimator& shapeEstimatorFor(double alpha_min, double alpha_max, double step, double tau)
{
  struct Memo
  {
    double alpha_min, alpha_max, step, tau;
    ShapeEstimator estimator;
  };
  thread_local std::optional<Memo> memo;
  if (!memo || memo->alpha_min != alpha_min || memo->alpha_max != alpha_max || memo->step != step || memo->tau != tau)
    memo.emplace(Memo{alpha_min, alpha_max, step, tau, ShapeEstimator(alpha_min, alpha_max, step, tau)});
  return memo->estimator;
}

double robustResidualScale(std::vector<double> residuals)
{
  if (residuals.empty()) return 1.0;
  constexpr double kChi3Median = 1.5381722;  // sqrt of the chi-square(3) median, 2.365974
  const auto mid = residuals.begin() + residuals.size() / 2;
  std::nth_element(residuals.begin(), mid, residuals.end());
  return std::max(1e-3, *mid / kChi3Median);
}

}  // namespace swslam::graph

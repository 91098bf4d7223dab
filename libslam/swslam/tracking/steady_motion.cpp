#include <swslam/tracking/steady_motion.h>

#include <algorithm>

namespace swslam::tracking
{
void SteadyMotion::add(const mrpt::poses::CPose2D& motion, const std::optional<mrpt::poses::CPose2D>& predicted)
{
  const std::optional<mrpt::poses::CPose2D> p =
      predicted ? predicted : (motions_.empty() ? std::nullopt : std::optional(motions_.back()));
  if (p)
  {
    const double dx = motion.x() - p->x(), dy = motion.y() - p->y();
    squared_errors_.push_back(dx * dx + dy * dy);
    if (squared_errors_.size() > kHistory - 1) squared_errors_.pop_front();
  }
  motions_.push_back(motion);
  if (motions_.size() > kHistory) motions_.pop_front();
}

double SteadyMotion::costPerM2(const TrackingParams& p) const
{
  if (p.steady_prior_cost <= 0 || squared_errors_.size() < kMinChanges || motions_.size() < kStepWindow)
    return 0;
  double step = 0;
  for (size_t k = motions_.size() - kStepWindow; k < motions_.size(); k++) step += motions_[k].norm();
  if (step / kStepWindow < p.steady_min_step) return 0;
  double sum_sq = 0;
  for (double e2 : squared_errors_) sum_sq += e2;
  const double var = std::max(sum_sq / squared_errors_.size(), p.steady_sigma_min * p.steady_sigma_min);
  return p.steady_prior_cost / var;
}

double SteadyMotion::predictionVariance(double min_variance, double unknown) const
{
  if (squared_errors_.size() < kMinChanges) return unknown;
  double sum_sq = 0;
  for (double e2 : squared_errors_) sum_sq += e2;
  return std::max(sum_sq / squared_errors_.size(), min_variance);
}

}  // namespace swslam::tracking

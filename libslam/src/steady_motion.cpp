#include "swslam/tracking/steady_motion.h"

#include <algorithm>

namespace swslam
{
void SteadyMotion::add(const mrpt::poses::CPose2D& motion)
{
  motions_.push_back(motion);
  if (motions_.size() > kHistory) motions_.pop_front();
}

double SteadyMotion::costPerM2(const CorrelativeParams& p) const
{
  if (p.steady_prior_cost <= 0 || motions_.size() < kMinChanges + 1) return 0;
  double step = 0;
  for (size_t k = motions_.size() - kStepWindow; k < motions_.size(); k++) step += motions_[k].norm();
  if (step / kStepWindow < p.steady_min_step) return 0;
  double sum_sq = 0;
  for (size_t k = 1; k < motions_.size(); k++)
  {
    const double dx = motions_[k].x() - motions_[k - 1].x(), dy = motions_[k].y() - motions_[k - 1].y();
    sum_sq += dx * dx + dy * dy;
  }
  const double var = std::max(sum_sq / (motions_.size() - 1), p.steady_sigma_min * p.steady_sigma_min);
  return p.steady_prior_cost / var;
}

}  // namespace swslam

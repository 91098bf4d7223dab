#include <swslam/io/carmen_rules.h>

#include <algorithm>
#include <cmath>

namespace swslam::io
{
SaturationDetector::SaturationDetector(double rel_tol, size_t min_count)
    : rel_tol_(rel_tol), min_count_(min_count)
{
}

void SaturationDetector::add(double range)
{
  if (!std::isfinite(range) || range <= 0) return;
  if (range > max_)
  {
    max_ = range;
    // Drop readings that fell out of the cluster; amortised by pruning only when the
    // buffer doubled since the last pruning.
    if (near_top_.size() > 2 * pruned_size_ + 16) prune();
  }
  if (range >= max_ * (1 - rel_tol_)) near_top_.push_back(range);
}

void SaturationDetector::prune()
{
  const double low = max_ * (1 - rel_tol_);
  near_top_.erase(std::remove_if(near_top_.begin(), near_top_.end(),
                                 [low](double r) { return r < low; }),
                  near_top_.end());
  pruned_size_ = near_top_.size();
}

size_t SaturationDetector::clusterSize() const
{
  const double low = max_ * (1 - rel_tol_);
  return std::count_if(near_top_.begin(), near_top_.end(), [low](double r) { return r >= low; });
}

std::optional<double> SaturationDetector::threshold() const
{
  if (clusterSize() < std::max<size_t>(min_count_, 1)) return std::nullopt;
  const double low = max_ * (1 - rel_tol_);
  double smallest = max_;
  for (double r : near_top_)
    if (r >= low) smallest = std::min(smallest, r);
  return smallest;
}

double medianPositivePeriod(const std::vector<double>& times, double max_gap, double fallback)
{
  std::vector<double> periods;
  for (size_t i = 1; i < times.size(); i++)
  {
    const double d = times[i] - times[i - 1];
    if (d > 0 && d <= max_gap) periods.push_back(d);
  }
  if (periods.empty()) return fallback;
  auto mid = periods.begin() + periods.size() / 2;
  std::nth_element(periods.begin(), mid, periods.end());
  return *mid;
}

double TimestampSequence::next(double t, TimestampIssue& issue)
{
  issue = TimestampIssue::None;
  if (started_)
  {
    if (t <= prev_)
      issue = TimestampIssue::NonIncreasing;
    else if (t - prev_ > max_gap_)
      issue = TimestampIssue::ForwardJump;
    if (issue != TimestampIssue::None && repair_) t = prev_ + period_;
  }
  started_ = true;
  prev_ = t;
  return t;
}

}  // namespace swslam::io

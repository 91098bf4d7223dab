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
  Bin& bin = bins_[static_cast<int64_t>(std::floor(std::log(range) / std::log1p(rel_tol_)))];
  bin.min = bin.count == 0 ? range : std::min(bin.min, range);
  bin.count++;
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

std::optional<std::pair<double, size_t>> SaturationDetector::pileBelowGlitches() const
{
  const size_t min_count = std::max<size_t>(min_count_, 1);
  const auto count = [&](int64_t key) {
    const auto it = bins_.find(key);
    return it == bins_.end() ? size_t(0) : it->second.count;
  };
  size_t above = 0;
  for (auto it = bins_.rbegin(); it != bins_.rend() && above < min_count; above += it->second.count, ++it)
  {
    const int64_t key = it->first;
    const size_t band = it->second.count + count(key - 1), below = count(key - 2) + count(key - 3);
    if (band < min_count || band < 3 * (below + 1)) continue;
    // The pile's own bin when it holds the pile alone: the lower bin is then real readings.
    const auto lower = bins_.find(key - 1);
    const double smallest = it->second.count >= min_count || lower == bins_.end()
                                ? it->second.min
                                : std::min(it->second.min, lower->second.min);
    return std::make_pair(smallest, above);
  }
  return std::nullopt;
}

std::optional<double> SaturationDetector::threshold() const
{
  if (clusterSize() < std::max<size_t>(min_count_, 1))
  {
    const auto pile = pileBelowGlitches();
    if (!pile) return std::nullopt;
    return pile->first;
  }
  const double low = max_ * (1 - rel_tol_);
  double smallest = max_;
  for (double r : near_top_)
    if (r >= low) smallest = std::min(smallest, r);
  return smallest;
}

size_t SaturationDetector::glitchesAbove() const
{
  if (clusterSize() >= std::max<size_t>(min_count_, 1)) return 0;
  const auto pile = pileBelowGlitches();
  return pile ? pile->second : 0;
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

#include <swslam/tracking/motion_prediction.h>

#include <algorithm>

namespace swslam::tracking
{
double intervalRatio(double dt_now, double dt_prev, double max_ratio, double horizon)
{
  if (!(dt_now > 0) || !(dt_prev > 0)) return 1.0;
  const double lowest = std::min(1 / max_ratio, dt_now / horizon);
  const double highest = std::max(max_ratio, horizon / dt_prev);
  return std::clamp(dt_now / dt_prev, lowest, highest);
}

}  // namespace swslam::tracking

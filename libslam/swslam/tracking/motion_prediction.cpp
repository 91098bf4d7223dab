#include <swslam/tracking/motion_prediction.h>

#include <algorithm>

namespace swslam::tracking
{
double intervalRatio(double dt_now, double dt_prev, double max_ratio)
{
  if (!(dt_now > 0) || !(dt_prev > 0)) return 1.0;
  return std::clamp(dt_now / dt_prev, 1 / max_ratio, max_ratio);
}

}  // namespace swslam::tracking

#include <swslam/common/unix_time.h>

#include <cmath>
#include <utility>

namespace swslam::common
{
bool plausibleUnixTime(double t) { return std::isfinite(t) && t >= 0 && t < kLatestPlausibleTime; }

std::string timeUnitHint(double t)
{
  if (plausibleUnixTime(t) || !(t > 0)) return "";
  // The smallest unit that brings it in: a stamp in ns divided by 1e6 still looks like ms.
  static const std::pair<double, const char*> kUnits[] = {{1e3, "milliseconds"}, {1e6, "microseconds"}, {1e9, "nanoseconds"}};
  for (const auto& [scale, unit] : kUnits)
    if (plausibleUnixTime(t / scale) && t / scale >= 1e8)  // 1973 on: a real clock, not a count
      return std::string(" (") + unit + " rather than seconds?)";
  return "";
}

}  // namespace swslam::common

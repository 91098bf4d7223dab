#include <swslam/eval/error_stats.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace swslam::eval
{
ErrorStats errorStats(std::vector<double> v)
{
  ErrorStats s;
  s.n = v.size();
  if (v.empty())
  {
    s.rmse = s.mean = s.stddev = s.median = s.max = std::numeric_limits<double>::quiet_NaN();
    return s;
  }
  double sum = 0, sum_sq = 0;
  for (const double x : v) { sum += x; sum_sq += x * x; }
  s.mean = sum / s.n;
  s.rmse = std::sqrt(sum_sq / s.n);
  double dev = 0;
  for (const double x : v) dev += (x - s.mean) * (x - s.mean);
  s.stddev = s.n > 1 ? std::sqrt(dev / (s.n - 1)) : 0.0;
  std::sort(v.begin(), v.end());
  s.median = s.n % 2 ? v[s.n / 2] : 0.5 * (v[s.n / 2 - 1] + v[s.n / 2]);
  s.max = v.back();
  return s;
}

}  // namespace swslam::eval

#pragma once
// Summary statistics of a set of non-negative errors.

#include <cstddef>
#include <vector>

namespace swslam::eval
{
struct ErrorStats
{
  size_t n = 0;
  double rmse = 0, mean = 0, stddev = 0, median = 0, max = 0;  ///< NaN when n == 0
};

/** RMSE, mean, sample standard deviation (n - 1; 0 for a single value), median (mean of
 * the two middle values for even n) and maximum of `values`. */
ErrorStats errorStats(std::vector<double> values);

}  // namespace swslam::eval

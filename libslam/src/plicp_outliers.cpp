#include "swslam/plicp/outliers.h"

#include <algorithm>
#include <cmath>

namespace swslam::plicp
{
std::vector<Correspondence> keepNearestPerReference(const std::vector<Correspondence>& in,
                                                    int ref_size)
{
  // Index into `in` of the nearest match of each j1 (per-thread buffer: no allocation per call).
  thread_local std::vector<int> owner;
  owner.assign(ref_size, -1);
  for (int k = 0; k < static_cast<int>(in.size()); k++)
  {
    int& o = owner[in[k].j1];
    if (o < 0 || in[k].dist2 < in[o].dist2) o = k;
  }
  std::vector<Correspondence> out;
  out.reserve(in.size());
  for (int k = 0; k < static_cast<int>(in.size()); k++)
    if (owner[in[k].j1] == k) out.push_back(in[k]);
  return out;
}

std::vector<Correspondence> trimByError(const std::vector<Correspondence>& in,
                                        const std::vector<double>& errors, double keep_fraction,
                                        double adaptive_quantile, double adaptive_mult)
{
  if (in.empty()) return {};
  thread_local std::vector<double> sorted;  // per-thread buffer: no allocation per call
  sorted.assign(errors.begin(), errors.end());
  auto rank = [&](double q) {
    return std::min(sorted.size() - 1,
                    static_cast<size_t>(std::ceil(q * sorted.size())) - (q > 0 ? 1 : 0));
  };
  // Two order statistics with two partial partitions: the smaller rank first, then the
  // larger one inside the upper part (shorter than the lower one for the usual quantiles).
  const size_t k_keep = rank(keep_fraction), k_adapt = rank(adaptive_quantile);
  const size_t k_hi = std::max(k_keep, k_adapt), k_lo = std::min(k_keep, k_adapt);
  std::nth_element(sorted.begin(), sorted.begin() + k_lo, sorted.end());
  if (k_hi > k_lo) std::nth_element(sorted.begin() + k_lo + 1, sorted.begin() + k_hi, sorted.end());
  const double threshold = std::min(sorted[k_keep], adaptive_mult * sorted[k_adapt]);
  std::vector<Correspondence> out;
  out.reserve(in.size());
  for (size_t k = 0; k < in.size(); k++)
    if (errors[k] <= threshold) out.push_back(in[k]);
  return out;
}

}  // namespace swslam::plicp

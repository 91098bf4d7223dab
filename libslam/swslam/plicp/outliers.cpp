#include <swslam/plicp/outliers.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace swslam::plicp
{
void keepNearestPerReference(std::vector<Correspondence>& cs, int ref_size)
{
  // Index into `cs` of the nearest match of each j1 (per-thread buffer: no allocation per call).
  thread_local std::vector<int> owner;
  owner.assign(ref_size, -1);
  const int n = static_cast<int>(cs.size());
  for (int k = 0; k < n; k++)
  {
    int& o = owner[cs[k].j1];
    if (o < 0 || cs[k].dist2 < cs[o].dist2) o = k;
  }
  int w = 0;
  for (int k = 0; k < n; k++)
    if (owner[cs[k].j1] == k) cs[w++] = cs[k];  // w <= k: the owner entries read stay intact
  cs.resize(w);
}

void trimByError(std::vector<Correspondence>& cs, std::vector<double>& errors,
                 double keep_fraction, double adaptive_quantile, double adaptive_mult)
{
  if (cs.empty())
  {
    errors.clear();
    return;
  }
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
  size_t w = 0;
  for (size_t k = 0; k < cs.size(); k++)
    if (errors[k] <= threshold)
    {
      cs[w] = cs[k];
      errors[w++] = errors[k];
    }
  cs.resize(w);
  errors.resize(w);
}

}  // namespace swslam::plicp

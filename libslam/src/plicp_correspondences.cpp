#include "swslam/plicp/correspondences.h"

#include <cmath>
#include <limits>

namespace swslam::plicp
{
namespace
{
constexpr double kTwoPi = 2 * M_PI;

/** Lower bound of the distance from a point at range P to any point whose bearing differs
 * by `delta` in [0, pi]: the distance to the ray at that bearing. */
double bearingLowerBound(double P, double delta)
{
  return delta < M_PI_2 ? P * std::sin(delta) : P;
}

/** Candidate (distance, index) ordering: nearer first, then lower index. */
constexpr int kNone = std::numeric_limits<int>::max();

bool better(double d, int k, double best_d, int best_k)
{
  return d < best_d || (d == best_d && best_k != kNone && k < best_k);
}

/** Walks the reference scan from `start` in one direction (`step` = +1 or -1), updating
 * (best_d, best_k). `delta(k, wrapped)` is the bearing offset of ray k from the point,
 * growing along the walk. Jumps over runs of rays whose ranges keep them farther than best. */
template <class DeltaFn>
void walk(const Scan& ref, const ReferenceIndex& idx, const Eigen::Vector2d& p, double P,
          int start, bool wrapped, int step, DeltaFn delta, double& best_d, int& best_k)
{
  const int n = static_cast<int>(ref.size());
  const auto& bigger = step > 0 ? idx.up_bigger : idx.down_bigger;
  const auto& smaller = step > 0 ? idx.up_smaller : idx.down_smaller;
  int k = start;
  for (int guard = 0; guard <= 2 * n; guard++)
  {
    if (k < 0 || k >= n)
    {
      // Walks wrap around even on partial scans: across the blind sector, rays at the other
      // end of the scan can be the nearest ones.
      if (wrapped) return;
      wrapped = true;
      k = k < 0 ? n - 1 : 0;
    }
    const double dk = delta(k, wrapped);
    if (dk > M_PI || bearingLowerBound(P, dk) > best_d) return;  // nothing beyond can be nearer
    const double d = (ref.points[k] - p).norm();
    if (better(d, k, best_d, best_k))
    {
      best_d = d;
      best_k = k;
    }
    // Rays up to the next longer (shorter) one are no farther (nearer) from the origin than
    // ray k, so their distance to p is at least |P - r_k|: skip them when that beats nothing.
    const double r = ref.ranges[k];
    int next = k + step;
    if (P - r > best_d) next = bigger[k];
    else if (r - P > best_d) next = smaller[k];
    k = next;
  }
}
}  // namespace

ReferenceIndex::ReferenceIndex(const Scan& ref)
{
  const int n = static_cast<int>(ref.size());
  up_bigger.assign(n, n);
  up_smaller.assign(n, n);
  down_bigger.assign(n, -1);
  down_smaller.assign(n, -1);
  const auto& r = ref.ranges;
  // Each table entry follows the chain of its neighbour: amortized O(n).
  for (int i = n - 2; i >= 0; i--)
  {
    int j = i + 1;
    while (j < n && r[j] <= r[i]) j = up_bigger[j];
    up_bigger[i] = j;
    j = i + 1;
    while (j < n && r[j] >= r[i]) j = up_smaller[j];
    up_smaller[i] = j;
  }
  for (int i = 1; i < n; i++)
  {
    int j = i - 1;
    while (j >= 0 && r[j] <= r[i]) j = down_bigger[j];
    down_bigger[i] = j;
    j = i - 1;
    while (j >= 0 && r[j] >= r[i]) j = down_smaller[j];
    down_smaller[i] = j;
  }
  if (n >= 2)
  {
    const double step = ref.aperture / std::max<size_t>(1, ref.beam_count - 1);
    circular = ref.aperture + 2 * step >= kTwoPi;
  }
}

int secondPoint(const Scan& ref, bool circular, int j1, const Eigen::Vector2d& p,
                double min_segment)
{
  const int n = static_cast<int>(ref.size());
  constexpr int kMaxWalk = 8;  // rays walked along the scan to reach min_segment
  // The first ray on one side of j1 at least min_segment away from it, or -1.
  auto along = [&](int step) {
    for (int s = 1; s <= kMaxWalk && s < n; s++)
    {
      int k = j1 + step * s;
      if (circular) k = (k + n) % n;
      if (k < 0 || k >= n || k == j1) return -1;
      if ((ref.points[k] - ref.points[j1]).norm() >= min_segment) return k;
    }
    return -1;
  };
  const int lo = along(-1), hi = along(+1);
  if (lo < 0 || hi < 0) return std::max(lo, hi);
  return (ref.points[lo] - p).squaredNorm() <= (ref.points[hi] - p).squaredNorm() ? lo : hi;
}

std::vector<Correspondence> findCorrespondences(const Scan& ref, const ReferenceIndex& index,
                                                const std::vector<Eigen::Vector2d>& cur_in_ref,
                                                double max_dist, double min_segment)
{
  std::vector<Correspondence> out;
  const int n = static_cast<int>(ref.size());
  if (n < 2) return out;
  out.reserve(cur_in_ref.size());
  int up = 0;  // first reference ray with angle >= the point's bearing (n if none)
  for (size_t i = 0; i < cur_in_ref.size(); i++)
  {
    const Eigen::Vector2d& p = cur_in_ref[i];
    const double P = p.norm();
    const double phi = std::atan2(p.y(), p.x());
    // Move the start from the previous point's position: O(1) expected for ordered scans.
    while (up < n && ref.angles[up] < phi) up++;
    while (up > 0 && ref.angles[up - 1] >= phi) up--;

    double best_d = max_dist;
    int best_k = kNone;
    // Counter-clockwise from the bearing, then clockwise; offsets grow along each walk.
    walk(ref, index, p, P, up, false, +1,
         [&](int k, bool wrapped) { return ref.angles[k] - phi + (wrapped ? kTwoPi : 0); },
         best_d, best_k);
    walk(ref, index, p, P, up - 1, false, -1,
         [&](int k, bool wrapped) { return phi - ref.angles[k] + (wrapped ? kTwoPi : 0); },
         best_d, best_k);
    if (best_k == kNone) continue;
    const int j2 = secondPoint(ref, index.circular, best_k, p, min_segment);
    if (j2 < 0) continue;
    out.push_back({static_cast<int>(i), best_k, j2, best_d});
  }
  return out;
}

std::vector<Correspondence> findCorrespondencesBruteForce(
    const Scan& ref, const std::vector<Eigen::Vector2d>& cur_in_ref, double max_dist,
    double min_segment)
{
  std::vector<Correspondence> out;
  const int n = static_cast<int>(ref.size());
  if (n < 2) return out;
  const ReferenceIndex index(ref);
  for (size_t i = 0; i < cur_in_ref.size(); i++)
  {
    double best_d = max_dist;
    int best_k = -1;
    for (int k = 0; k < n; k++)
    {
      const double d = (ref.points[k] - cur_in_ref[i]).norm();
      if (d < best_d)  // strict: the lowest index wins ties
      {
        best_d = d;
        best_k = k;
      }
    }
    if (best_k < 0) continue;
    const int j2 = secondPoint(ref, index.circular, best_k, cur_in_ref[i], min_segment);
    if (j2 < 0) continue;
    out.push_back({static_cast<int>(i), best_k, j2, best_d});
  }
  return out;
}

}  // namespace swslam::plicp

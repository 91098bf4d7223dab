#include <swslam/plicp/correspondences.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace swslam::plicp
{
namespace
{
constexpr int kNone = std::numeric_limits<int>::max();

/** Candidate (squared distance, index) ordering: nearer first, then lower index. */
bool better(double d2, int k, double best_d2, int best_k)
{
  return d2 < best_d2 || (d2 == best_d2 && best_k != kNone && k < best_k);
}

/** Walks the reference scan from `start` in one direction (`step` = +1 counter-clockwise,
 * -1 clockwise), updating (best_d2, best_k). Trig-free: the bearing offset of ray k from the
 * point is tracked with pseudo-angles (monotone in the angle, range 4 per turn) and bounded
 * with cross and dot products. Stops when nothing beyond can be nearer; jumps over runs of
 * rays whose ranges keep them farther than the best so far. `others_d2` gets a lower bound on
 * the squared distance of every ray the walk covers except the best one: the distances it
 * computed, and the bounds that let it stop or jump. */
void walk(const sensor::Scan& ref, const ReferenceIndex& idx, const Eigen::Vector2d& p, double P,
          double p_pseudo, int start, int step, double& best_d2_io, int& best_k_io,
          double& others_d2_io)
{
  // Locals and raw pointers: the results live in registers during the walk (through the
  // references, every update would be a store the next comparison has to wait for).
  double best_d2 = best_d2_io, others_d2 = others_d2_io;
  int best_k = best_k_io;
  const int n = static_cast<int>(ref.size());
  const int* bigger = (step > 0 ? idx.up_bigger : idx.down_bigger).data();
  const int* smaller = (step > 0 ? idx.up_smaller : idx.down_smaller).data();
  const double* pseudo = idx.pseudo.data();
  const double* ranges = ref.ranges.data();
  const Eigen::Vector2d* dirs = idx.dirs.data();
  const Eigen::Vector2d* points = ref.points.data();
  const double px = p.x(), py = p.y();
  const auto done = [&]() {
    best_d2_io = best_d2;
    best_k_io = best_k;
    others_d2_io = others_d2;
  };
  bool wrapped = false;
  int k = start;
  for (int guard = 0; guard <= 2 * n; guard++)
  {
    if (k < 0 || k >= n)
    {
      // Walks wrap around even on partial scans: across the blind sector, rays at the other
      // end of the scan can be the nearest ones.
      if (wrapped) return done();
      wrapped = true;
      k = k < 0 ? n - 1 : 0;
    }
    // Offset in pseudo-angle units (2 = half a turn), growing along the walk.
    const double offset = step * (pseudo[k] - p_pseudo) + (wrapped ? 4.0 : 0.0);
    if (offset > 2.0) return done();  // past half a turn: the other walk covers the rest
    // Distance from p to the ray of bearing offset delta is at least P sin(delta) for delta
    // below 90 deg and at least P beyond it.
    const double ux = dirs[k].x(), uy = dirs[k].y();
    const double along = ux * px + uy * py, across = step * (uy * px - ux * py);
    const double bound = along >= 0 ? across : P;
    if (bound > 0 && bound * bound > best_d2)
    {
      others_d2 = std::min(others_d2, bound * bound);
      return done();
    }
    const double dx = points[k].x() - px, dy = points[k].y() - py;
    const double d2 = dx * dx + dy * dy;
    if (better(d2, k, best_d2, best_k))
    {
      if (best_k != kNone) others_d2 = std::min(others_d2, best_d2);
      best_d2 = d2;
      best_k = k;
    }
    else
      others_d2 = std::min(others_d2, d2);
    // Rays up to the next longer (shorter) one are no farther (nearer) from the origin than
    // ray k, so their distance to p is at least |P - r_k|: skip them when that beats nothing.
    const double gap = P - ranges[k];
    int next = k + step;
    if (gap * gap > best_d2)
    {
      next = gap > 0 ? bigger[k] : smaller[k];
      others_d2 = std::min(others_d2, gap * gap);
    }
    k = next;
  }
  others_d2 = 0;  // not reached (the walk ends within two turns); proves nothing
  done();
}
}  // namespace

double pseudoAngle(double x, double y)
{
  // "Diamond angle": 0..4 over a turn from +x, counter-clockwise; shifted to [-2, 2).
  double a;
  if (y >= 0) a = x >= 0 ? y / (x + y) : 1 - x / (-x + y);
  else a = x < 0 ? 2 - y / (-x - y) : 3 + x / (x - y);
  if (!(x != 0 || y != 0)) a = 0;
  return a >= 2 ? a - 4 : a;
}

ReferenceIndex::ReferenceIndex(const sensor::Scan& ref, double min_segment_length)
    : min_segment(min_segment_length)
{
  const int n = static_cast<int>(ref.size());
  up_bigger.assign(n, n);
  up_smaller.assign(n, n);
  down_bigger.assign(n, -1);
  down_smaller.assign(n, -1);
  const auto& r = ref.ranges;
  dirs.resize(n);
  pseudo.resize(n);
  for (int i = 0; i < n; i++)
  {
    dirs[i] = ref.points[i] / ref.ranges[i];
    pseudo[i] = pseudoAngle(dirs[i].x(), dirs[i].y());
    // Keep the sequence non-decreasing at +pi, where the pseudo-angle wraps to -2.
    if (i > 0 && pseudo[i] < pseudo[i - 1]) pseudo[i] += 4;
  }
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
    circular = ref.aperture + 2 * step >= 2 * M_PI;
  }
  segment_lo.resize(n);
  segment_hi.resize(n);
  normal_lo.assign(n, Eigen::Vector2d::Zero());
  normal_hi.assign(n, Eigen::Vector2d::Zero());
  for (int j = 0; j < n; j++)
  {
    segment_lo[j] = segmentEnd(ref, circular, j, -1, min_segment);
    segment_hi[j] = segmentEnd(ref, circular, j, +1, min_segment);
    if (segment_lo[j] >= 0) normal_lo[j] = segmentNormal(ref.points[j], ref.points[segment_lo[j]]);
    if (segment_hi[j] >= 0) normal_hi[j] = segmentNormal(ref.points[j], ref.points[segment_hi[j]]);
  }
}

int segmentEnd(const sensor::Scan& ref, bool circular, int j1, int step, double min_segment)
{
  const int n = static_cast<int>(ref.size());
  constexpr int kMaxWalk = 8;  // rays walked along the scan to reach min_segment
  const double min2 = min_segment * min_segment;
  int last = -1;
  for (int s = 1; s <= kMaxWalk && s < n; s++)
  {
    int k = j1 + step * s;
    if (circular) k = (k + n) % n;
    if (k < 0 || k >= n || k == j1) break;
    if ((ref.points[k] - ref.points[j1]).squaredNorm() >= min2) return k;
    last = k;
  }
  return last;  // none that far: the farthest walked (close surfaces, dense beams)
}

namespace
{
/** Of the two candidate ends (either may be -1), the one closer to p. */
int closerEnd(const sensor::Scan& ref, int lo, int hi, const Eigen::Vector2d& p)
{
  if (lo < 0 || hi < 0) return std::max(lo, hi);
  return (ref.points[lo] - p).squaredNorm() <= (ref.points[hi] - p).squaredNorm() ? lo : hi;
}
}  // namespace

int secondPoint(const sensor::Scan& ref, bool circular, int j1, const Eigen::Vector2d& p,
                double min_segment)
{
  return closerEnd(ref, segmentEnd(ref, circular, j1, -1, min_segment),
                   segmentEnd(ref, circular, j1, +1, min_segment), p);
}

namespace
{
/** Both walks for point p; returns the best ray (kNone if none within sqrt(best_d2)). */
int search(const sensor::Scan& ref, const ReferenceIndex& index, const Eigen::Vector2d& p, int& up,
           double& best_d2, double& others_d2)
{
  const int n = static_cast<int>(ref.size());
  const double P = p.norm();
  const double pp = pseudoAngle(p.x(), p.y());
  // Move the start from the previous point's position: O(1) expected for ordered scans.
  while (up < n && index.pseudo[up] < pp) up++;
  while (up > 0 && index.pseudo[up - 1] >= pp) up--;
  int best_k = kNone;
  walk(ref, index, p, P, pp, up, +1, best_d2, best_k, others_d2);
  walk(ref, index, p, P, pp, up - 1, -1, best_d2, best_k, others_d2);
  return best_k;
}

template <bool kRemember>
std::vector<Correspondence> find(const sensor::Scan& ref, const ReferenceIndex& index,
                                 const std::vector<Eigen::Vector2d>& cur_in_ref, double max_dist,
                                 SearchMemory* memory)
{
  std::vector<Correspondence> out;
  const int n = static_cast<int>(ref.size());
  if (n < 2) return out;
  out.reserve(cur_in_ref.size());
  const double max_d2 = max_dist * max_dist;
  // Slack on the proofs, for the rounding of the distances and bounds compared.
  constexpr double kSlack = 1e-9;
  if constexpr (kRemember)
  {
    if (memory->valid.size() != cur_in_ref.size())
    {
      memory->anchor.assign(cur_in_ref.size(), Eigen::Vector2d::Zero());
      memory->nearest.assign(cur_in_ref.size(), -1);
      memory->others.assign(cur_in_ref.size(), 0.0);
      memory->valid.assign(cur_in_ref.size(), 0);
    }
  }
  int up = 0;  // first reference ray at or after the point's bearing (n if none)
  for (size_t i = 0; i < cur_in_ref.size(); i++)
  {
    const Eigen::Vector2d& p = cur_in_ref[i];
    double best_d2 = max_d2;
    int best_k = kNone;
    bool known = false;
    if constexpr (kRemember)
    {
      if (memory->valid[i])
      {
        // Every ray but nearest[i] is at least `clear` from p.
        const double clear = memory->others[i] - (p - memory->anchor[i]).norm() - kSlack;
        const int j = memory->nearest[i];
        if (j >= 0)
        {
          const double d2 = (ref.points[j] - p).squaredNorm();
          if (clear > 0 && d2 < clear * clear)  // j is still the unique nearest ray
          {
            known = true;
            if (d2 < max_d2)
            {
              best_d2 = d2;
              best_k = j;
            }
          }
        }
        else if (clear >= max_dist)
          known = true;  // still nothing within the radius
        if (known) memory->reused++;
      }
    }
    if (!known)
    {
      double others_d2 = std::numeric_limits<double>::infinity();
      best_k = search(ref, index, p, up, best_d2, others_d2);
      if constexpr (kRemember)
      {
        memory->searched++;
        memory->anchor[i] = p;
        memory->nearest[i] = best_k == kNone ? -1 : best_k;
        memory->others[i] = std::sqrt(others_d2);
        memory->valid[i] = 1;
      }
    }
    if (best_k == kNone) continue;
    const int j2 = closerEnd(ref, index.segment_lo[best_k], index.segment_hi[best_k], p);
    if (j2 < 0) continue;
    out.push_back({static_cast<int>(i), best_k, j2, best_d2});
  }
  return out;
}
}  // namespace

std::vector<Correspondence> findCorrespondences(const sensor::Scan& ref, const ReferenceIndex& index,
                                                const std::vector<Eigen::Vector2d>& cur_in_ref,
                                                double max_dist)
{
  return find<false>(ref, index, cur_in_ref, max_dist, nullptr);
}

std::vector<Correspondence> findCorrespondences(const sensor::Scan& ref, const ReferenceIndex& index,
                                                const std::vector<Eigen::Vector2d>& cur_in_ref,
                                                double max_dist, SearchMemory& memory)
{
  return find<true>(ref, index, cur_in_ref, max_dist, &memory);
}

std::vector<Correspondence> findCorrespondencesBruteForce(
    const sensor::Scan& ref, const std::vector<Eigen::Vector2d>& cur_in_ref, double max_dist,
    double min_segment)
{
  std::vector<Correspondence> out;
  const int n = static_cast<int>(ref.size());
  if (n < 2) return out;
  const ReferenceIndex index(ref, min_segment);
  for (size_t i = 0; i < cur_in_ref.size(); i++)
  {
    double best_d2 = max_dist * max_dist;
    int best_k = -1;
    for (int k = 0; k < n; k++)
    {
      const double d2 = (ref.points[k] - cur_in_ref[i]).squaredNorm();
      if (d2 < best_d2)  // strict: the lowest index wins ties
      {
        best_d2 = d2;
        best_k = k;
      }
    }
    if (best_k < 0) continue;
    const int j2 = secondPoint(ref, index.circular, best_k, cur_in_ref[i], min_segment);
    if (j2 < 0) continue;
    out.push_back({static_cast<int>(i), best_k, j2, best_d2});
  }
  return out;
}

}  // namespace swslam::plicp

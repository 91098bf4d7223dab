#pragma once
// Point-to-line correspondences of PLICP (paper sec. II.A, after Censi 2008): for each
// current point, transformed into the reference frame, the nearest reference point j1
// and its closer neighbour j2 along the scan.

#include <swslam/sensor/scan.h>

#include <Eigen/Core>
#include <vector>

namespace swslam::plicp
{
/** One point-to-line correspondence, indices into the valid rays of the scans. */
struct Correspondence
{
  int i = -1;   ///< current point
  int j1 = -1;  ///< nearest reference point
  int j2 = -1;  ///< neighbour of j1 along the scan (see secondPoint())
  double dist2 = 0;  ///< squared point-to-point distance from the transformed current point to j1
  bool operator==(const Correspondence& o) const { return i == o.i && j1 == o.j1 && j2 == o.j2; }
};

/** Precomputed per reference scan: jump tables over ranges (Censi's "up/down bigger/smaller")
 * that let the search skip runs of rays that cannot be closer than the best so far. */
struct ReferenceIndex
{
  std::vector<int> up_bigger, up_smaller, down_bigger, down_smaller;
  std::vector<Eigen::Vector2d> dirs;  ///< unit direction of each ray
  std::vector<double> pseudo;         ///< pseudoAngle() of each ray, non-decreasing
  std::vector<int> segment_lo, segment_hi;  ///< segmentEnd() on each side of each ray
  /// Unit normal of the segment from each ray to segment_lo / segment_hi (see segmentNormal()).
  std::vector<Eigen::Vector2d> normal_lo, normal_hi;
  bool circular = false;  ///< the scan closes on itself (aperture ~ 360 deg)
  double min_segment = 0;  ///< [m] see secondPoint()

  ReferenceIndex(const sensor::Scan& ref, double min_segment_length);
};

/** Unit normal of the reference segment j1-j2: (q1 - q2) normalized, turned by +90 deg. */
inline Eigen::Vector2d segmentNormal(const Eigen::Vector2d& q1, const Eigen::Vector2d& q2)
{
  const Eigen::Vector2d e = (q1 - q2).normalized();
  return {-e.y(), e.x()};
}

/** segmentNormal() of a correspondence's j1-j2, from the index's tables when j2 is one of
 * j1's segment ends (always, for findCorrespondences()), computed otherwise. */
inline Eigen::Vector2d correspondenceNormal(const sensor::Scan& ref, const ReferenceIndex& index,
                                            const Correspondence& k)
{
  if (k.j2 == index.segment_lo[k.j1]) return index.normal_lo[k.j1];
  if (k.j2 == index.segment_hi[k.j1]) return index.normal_hi[k.j1];
  return segmentNormal(ref.points[k.j1], ref.points[k.j2]);
}

/** A cheap monotone stand-in for atan2(y, x): in [-2, 2), 2 per half turn. */
double pseudoAngle(double x, double y);

/** What the last full search of each current point proved, for findCorrespondences() to
 * reuse while the point moves little between iterations. Valid for one reference scan and one
 * current scan (indices of its points); a default-constructed memory is empty. For point i
 * searched at `anchor[i]`: `nearest[i]` is its nearest reference ray if one was within the
 * search radius (-1 otherwise), and every *other* reference ray is at least `others[i]` from
 * `anchor[i]`. At a new position p with delta = |p - anchor[i]|, every other ray is then at
 * least others[i] - delta from p (triangle inequality), so nearest[i] is still the unique
 * nearest ray when it is closer than that, and no ray is within r if others[i] - delta >= r. */
struct SearchMemory
{
  std::vector<Eigen::Vector2d> anchor;
  std::vector<int> nearest;
  std::vector<double> others;
  std::vector<char> valid;
  size_t reused = 0;    ///< points answered from the memory (statistics)
  size_t searched = 0;  ///< points searched
};

/** Fast search: expected O(n) over all current points. Starts each search from the previous
 * point's position in the reference scan, walks away from the point's bearing in both
 * directions and stops or jumps only when the skipped rays provably cannot be closer.
 * Returns, for each current point with a reference point within `max_dist`, its
 * correspondence (in increasing i). Ties are broken by the lower reference index. */
std::vector<Correspondence> findCorrespondences(const sensor::Scan& ref, const ReferenceIndex& index,
                                                const std::vector<Eigen::Vector2d>& cur_in_ref,
                                                double max_dist);

/** The same result, reusing and updating `memory` (see SearchMemory): a point whose last
 * search still proves its answer is not searched again. Over the iterations of one match the
 * points move by millimetres, and most are answered by one distance. */
std::vector<Correspondence> findCorrespondences(const sensor::Scan& ref, const ReferenceIndex& index,
                                                const std::vector<Eigen::Vector2d>& cur_in_ref,
                                                double max_dist, SearchMemory& memory);

/** Slow, obviously correct version: checks every reference point, and finds j2 by walking
 * the scan (secondPoint()). Same output as findCorrespondences() with an index built with
 * the same `min_segment`. */
std::vector<Correspondence> findCorrespondencesBruteForce(
    const sensor::Scan& ref, const std::vector<Eigen::Vector2d>& cur_in_ref, double max_dist,
    double min_segment = 0);

/** The second reference point j2 that, with j1, defines the local line. On each side of j1
 * along the scan (wrapping on circular scans) take the first ray at least `min_segment`
 * from j1, walking at most 8 rays, or the 8th if none is that far; of the two sides, the end
 * closer to `p`; -1 if the scan has no other ray. With min_segment = 0 this is Censi's choice,
 * the closer of j1-1 and j1+1. A longer segment keeps range noise from tilting the normal on
 * dense scans (doc/plicp.md). */
int secondPoint(const sensor::Scan& ref, bool circular, int j1, const Eigen::Vector2d& p,
                double min_segment);

/** The first ray from j1 in direction `step` (+1/-1) at least `min_segment` away, walking at
 * most 8 rays; if none is, the last ray walked; -1 if there is none in that direction. */
int segmentEnd(const sensor::Scan& ref, bool circular, int j1, int step, double min_segment);

}  // namespace swslam::plicp

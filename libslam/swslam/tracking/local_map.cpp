#include <swslam/tracking/local_map.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace swslam::tracking
{
using mrpt::poses::CPose2D;

namespace
{
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

/** The bins of the virtual sensor: the beams of `like`, counter-clockwise. */
struct Bins
{
  size_t n = 0;
  double first = 0, step = 0;  ///< bearing of bin 0 and between bins [rad]
  bool circular = false;       ///< as plicp::ReferenceIndex decides it
  int period = 0;              ///< bins per turn (circular sensors)
  double max_range = 0;        ///< [m] the sensor's
  std::vector<Eigen::Vector2d> dirs;

  explicit Bins(const sensor::Scan& like) : n(like.beam_count), max_range(like.max_range)
  {
    if (n < 2 || !(like.aperture > 0)) return;
    step = like.aperture / static_cast<double>(n - 1);
    first = -0.5 * like.aperture;
    circular = like.aperture + 2 * step >= 2 * M_PI;
    period = static_cast<int>(std::lround(2 * M_PI / step));
    dirs.resize(n);
    for (size_t k = 0; k < n; k++) dirs[k] = {std::cos(bearing(k)), std::sin(bearing(k))};
  }
  double bearing(size_t k) const { return first + step * static_cast<double>(k); }
  /** The bin nearest to bearing `a`, or -1 outside the field of view. */
  int nearest(double a) const
  {
    if (dirs.empty()) return -1;
    const double rel = std::fmod(std::fmod(a - first, 2 * M_PI) + 2 * M_PI, 2 * M_PI);  // [0, 2 pi)
    long k = std::lround(rel / step);
    if (circular)
      k %= period;
    else if (k >= static_cast<long>(n) && std::lround((rel - 2 * M_PI) / step) == 0)
      k = 0;  // just before bin 0
    return k < static_cast<long>(n) ? static_cast<int>(k) : -1;
  }
};

/** The z-buffer, filled one keyframe at a time from the newest: per bin, the newest keyframe's
 * nearest surface point (where the bin's ray crosses a segment, or an isolated point at its own
 * bearing), unless an older keyframe's is nearer by more than kSameSurface. */
struct ZBuffer
{
  std::vector<double> range;
  std::vector<Eigen::Vector2d> point;
  std::vector<int> layer;  ///< the keyframe (position in the map) the bin's point comes from
  int current = -1;        ///< the keyframe being drawn
  double max_range;        ///< [m] farther surfaces are not seen, and hide nothing
  ZBuffer(size_t n, double max_range)
      : range(n, std::numeric_limits<double>::infinity()), point(n), layer(n, -1), max_range(max_range)
  {
  }
  void offer(size_t k, double r, const Eigen::Vector2d& p)
  {
    if (!(r > 0 && r < max_range)) return;
    const double margin = layer[k] == current ? 0.0 : kSameSurface;
    if (r < range[k] - margin)
    {
      range[k] = r;
      point[k] = p;
      layer[k] = current;
    }
  }
};

/** Where the ray of direction `u` crosses segment a-b, or a non-positive range if it does not.
 * An end on the ray counts, to within the rounding of the scans' ray directions (MRPT's are
 * single precision: a keyframe seen from its own pose must give its own rays). */
double rayCrossing(const Eigen::Vector2d& u, const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  const double ca = cross(u, a), cb = cross(u, b);
  const double den = ca - cb;
  if (den == 0) return -1;  // along the ray
  const double t = ca / den, tol = 1e-4;
  if (t < -tol || t > 1 + tol) return -1;  // both ends on the same side of the ray's line
  return u.dot(a + std::clamp(t, 0.0, 1.0) * (b - a));
}

/** A map scan's surfaces in the virtual sensor's frame: its points with their bearings,
 * segments from point i to i + 1, and isolated points. */
struct Surfaces
{
  std::vector<Eigen::Vector2d> points;
  std::vector<double> bearings;
  std::vector<size_t> segments, isolated;
};

Surfaces surfacesSeenFrom(const MapScan& ms, const CPose2D& sensor_pose)
{
  Surfaces s;
  const sensor::Scan& scan = *ms.scan;
  const CPose2D t = (-sensor_pose) + ms.sensor_pose;
  const double c = std::cos(t.phi()), sn = std::sin(t.phi());
  s.points.reserve(scan.size());
  s.bearings.reserve(scan.size());
  bool linked_before = false;
  for (size_t i = 0; i < scan.size(); i++)
  {
    const Eigen::Vector2d& p = scan.points[i];
    s.points.emplace_back(t.x() + c * p.x() - sn * p.y(), t.y() + sn * p.x() + c * p.y());
    s.bearings.push_back(std::atan2(s.points.back().y(), s.points.back().x()));
    const bool linked_after = linkedRays(scan, i);
    if (linked_after) s.segments.push_back(i);
    if (!linked_before && !linked_after) s.isolated.push_back(i);
    linked_before = linked_after;
  }
  return s;
}

/** Draws one keyframe's surfaces: each segment on the bins within the bearings it subtends,
 * each isolated point on its nearest bin. */
void draw(const Surfaces& s, const Bins& bins, ZBuffer& z)
{
  const double last = static_cast<double>(bins.n - 1);
  // The bins within the bearings [from, to] (from <= to, both within a turn of bin 0).
  auto crossBins = [&](double from, double to, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    // Widened by the rounding of ray directions: rayCrossing() decides the bins at the ends.
    const double k0 = std::max(0.0, std::ceil((from - bins.first) / bins.step - 1e-3));
    const double k1 = std::min(last, std::floor((to - bins.first) / bins.step + 1e-3));
    for (double k = k0; k <= k1; k++)
    {
      const size_t i = static_cast<size_t>(k);
      const double r = rayCrossing(bins.dirs[i], a, b);
      z.offer(i, r, r * bins.dirs[i]);
    }
  };
  for (size_t i : s.segments)
  {
    const Eigen::Vector2d &a = s.points[i], &b = s.points[i + 1];
    // Beyond the sensor's range (each point of the segment is at least |a| - |b - a| away), or
    // through the sensor; otherwise it subtends the shorter arc from a to b.
    if (a.norm() - (b - a).norm() >= bins.max_range) continue;
    if (std::abs(cross(a, b)) < 1e-12 && a.dot(b) <= 0) continue;
    const double ta = s.bearings[i];
    const double d = std::remainder(s.bearings[i + 1] - ta, 2 * M_PI);
    // Bearings measured from bin 0 upwards: [lo, lo + |d|] with lo in [first, first + 2 pi).
    double lo = std::min(ta, ta + d);
    lo = bins.first + std::fmod(std::fmod(lo - bins.first, 2 * M_PI) + 2 * M_PI, 2 * M_PI);
    crossBins(lo, lo + std::abs(d), a, b);
    if (lo + std::abs(d) >= bins.first + 2 * M_PI)  // the arc wraps past bin 0's bearing
      crossBins(lo - 2 * M_PI, lo + std::abs(d) - 2 * M_PI, a, b);
  }
  for (size_t i : s.isolated)
  {
    const double r = s.points[i].norm();
    if (r >= bins.max_range) continue;  // (offer() would drop it)
    const int k = bins.nearest(s.bearings[i]);
    if (k >= 0) z.offer(static_cast<size_t>(k), r, s.points[i]);
  }
}

sensor::Scan fromZBuffer(const ZBuffer& z, const Bins& bins, const sensor::Scan& like, double min_range)
{
  sensor::Scan out = like;  // its sensor's geometry, none of its rays
  out.angles.clear();
  out.ranges.clear();
  out.points.clear();
  out.beam_index.clear();
  out.rejected = {};
  for (size_t k = 0; k < z.range.size(); k++)
  {
    const double r = z.range[k];
    if (!(r >= min_range && r < like.max_range)) continue;
    // Near the bin's bearing, so that the angles increase (an isolated point is within half a
    // bin of it; a crossing is on it).
    const double a = bins.bearing(k) + std::remainder(std::atan2(z.point[k].y(), z.point[k].x()) - bins.bearing(k), 2 * M_PI);
    out.angles.push_back(a);
    out.ranges.push_back(r);
    out.points.emplace_back(r * std::cos(a), r * std::sin(a));
    out.beam_index.push_back(static_cast<int>(k));
  }
  return out;
}
}  // namespace

bool linkedRays(const sensor::Scan& scan, size_t i)
{
  if (i + 1 >= scan.size() || scan.beam_index[i + 1] != scan.beam_index[i] + 1) return false;
  const Eigen::Vector2d d = scan.points[i + 1] - scan.points[i];
  const Eigen::Vector2d m = 0.5 * (scan.points[i + 1] + scan.points[i]);
  const double dn = d.norm(), mn = m.norm();
  if (dn == 0) return true;
  return std::abs(cross(m, d)) >= std::sin(kMinSurfaceAngle) * dn * mn;
}

sensor::Scan virtualScan(const std::vector<MapScan>& map, const CPose2D& sensor_pose, const sensor::Scan& like,
                         double min_range)
{
  const Bins bins(like);
  ZBuffer z(bins.dirs.size(), like.max_range);
  if (!bins.dirs.empty())
    for (z.current = 0; z.current < static_cast<int>(map.size()); z.current++)
      draw(surfacesSeenFrom(map[map.size() - 1 - z.current], sensor_pose), bins, z);
  return fromZBuffer(z, bins, like, min_range);
}

sensor::Scan virtualScanBruteForce(const std::vector<MapScan>& map, const CPose2D& sensor_pose,
                                   const sensor::Scan& like, double min_range)
{
  const Bins bins(like);
  ZBuffer z(bins.dirs.size(), like.max_range);
  for (z.current = 0; z.current < static_cast<int>(map.size()); z.current++)
  {
    const Surfaces s = surfacesSeenFrom(map[map.size() - 1 - z.current], sensor_pose);
    for (size_t k = 0; k < bins.dirs.size(); k++)
    {
      const Eigen::Vector2d& u = bins.dirs[k];
      for (size_t i : s.segments)
      {
        const double r = rayCrossing(u, s.points[i], s.points[i + 1]);
        z.offer(k, r, r * u);
      }
      for (size_t i : s.isolated)
        if (bins.nearest(s.bearings[i]) == static_cast<int>(k)) z.offer(k, s.points[i].norm(), s.points[i]);
    }
  }
  return fromZBuffer(z, bins, like, min_range);
}

plicp::MatchResult inReferenceFrame(const plicp::MatchResult& m, const CPose2D& to_match_frame)
{
  plicp::MatchResult out = m;
  out.pose = to_match_frame + m.pose;
  Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
  j.topLeftCorner<2, 2>() = Eigen::Rotation2Dd(to_match_frame.phi()).toRotationMatrix();
  out.covariance = j * m.covariance * j.transpose();
  return out;
}

}  // namespace swslam::tracking

#pragma once
// Scan-to-local-map matching (the role of Cartographer's scan-to-submap front end, kept with
// PLICP): the recent keyframes' scans, at their latest (optimized) poses, are rendered into a
// virtual scan, what the sensor would see of them from a given pose, and the new scan is
// matched against it instead of against the last keyframe alone.
//
// Rendering. Each keyframe scan is a set of surfaces in the world: the segment between two
// adjacent rays (consecutive beams) when it is not seen edge-on from that keyframe (a segment
// almost along the rays is a depth jump, not a surface), and the isolated points left over.
// Each bin of the virtual sensor (its beams' bearings) takes the nearest surface its ray
// crosses, a z-buffer: a wall any keyframe saw hides what other keyframes saw behind it, from
// the virtual sensor's viewpoint. Segments give the point where the bin's ray crosses them
// (a ray cast into the keyframes' polylines); an isolated point goes to its nearest bin,
// at its own position. Where keyframes saw the same surface (within kSameSurface along the
// ray) the newest one's is kept: the nearest of several noisy copies of a wall would pull the
// virtual scan towards the sensor.

#include <swslam/plicp/plicp.h>
#include <swslam/sensor/scan.h>

#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace swslam::tracking
{
/** One scan of the local map and where its sensor was (world frame). */
struct MapScan  ///< a map is a list of them, oldest first
{
  mrpt::poses::CPose2D sensor_pose;  ///< sensor pose in the world frame
  const sensor::Scan* scan = nullptr;
};

/** [m] Along a bin's ray, an older keyframe's surface replaces a newer one's only when it is
 * nearer by more than this (the same wall seen twice, range noise and pose error apart). */
constexpr double kSameSurface = 0.1;

/** The smallest angle [rad] between a keyframe's segment and its rays for it to be a surface. */
constexpr double kMinSurfaceAngle = 10.0 * M_PI / 180;

/** Whether rays i and i + 1 of `scan` bound a surface: adjacent beams, and the segment
 * between them at least kMinSurfaceAngle off the ray to its midpoint (from the scan's own
 * sensor). */
bool linkedRays(const sensor::Scan& scan, size_t i);

/** The virtual scan of `map` seen from `sensor_pose` (world frame) by a sensor with the
 * geometry of `like` (beam count, aperture, maximum range, label, mounting, timestamp): one ray
 * per bin that sees a surface at a range in [min_range, like.max_range). Its angles increase,
 * so it is a valid PLICP reference. */
sensor::Scan virtualScan(const std::vector<MapScan>& map, const mrpt::poses::CPose2D& sensor_pose,
                         const sensor::Scan& like, double min_range);

/** The same, slowly: every bin against every surface (for tests). */
sensor::Scan virtualScanBruteForce(const std::vector<MapScan>& map, const mrpt::poses::CPose2D& sensor_pose,
                                   const sensor::Scan& like, double min_range);

/** A match expressed in another reference frame: `to_match_frame` is the match's reference
 * frame in the new one. The pose is composed, the covariance rotated (J cov J', J the rotation
 * of `to_match_frame` on x, y). */
plicp::MatchResult inReferenceFrame(const plicp::MatchResult& m, const mrpt::poses::CPose2D& to_match_frame);

}  // namespace swslam::tracking

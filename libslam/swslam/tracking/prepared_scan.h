#pragma once
// A scan with its derived forms (STYLE 9): the points, how far a turn moves them, PLICP's
// reference form, the facing test's normals and the points the correlative search scores.
// Each form is built once, the first time a step needs it, and every later step reads that
// one: a scan that becomes no keyframe never builds its reference tables (22 us of the 0.36 ms
// a lake-short scan takes), and one that is never searched never thins its points.

#include <swslam/plicp/params.h>
#include <swslam/plicp/plicp.h>
#include <swslam/sensor/scan.h>
#include <swslam/tracking/ambiguity.h>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <vector>

namespace swslam::tracking
{
/** The parameters the derived forms depend on. */
struct ScanForms
{
  plicp::PlicpParams plicp;        ///< the reference tables' and normals' min_segment_length
  double search_resolution = 0.1;  ///< [m] the search's points at least this far apart...
  double search_max_range = 30;    ///< [m] ...and at most this far from the sensor
};

class PreparedScan
{
 public:
  PreparedScan(sensor::Scan scan, const ScanForms& forms);

  const sensor::Scan& scan() const { return scan_; }
  /** How far a turn moves the points (sensor::rotationLength): turns and translations compare. */
  double rotationLength() const { return rotation_length_; }
  /** PLICP's reference form of the scan, with its search tables. */
  const std::shared_ptr<const plicp::ReferenceScan>& reference() const;
  /** The normals of the facing test (facingNormals()). */
  const std::shared_ptr<const FacingNormals>& facing() const;
  /** The points the correlative search scores (correlative::thinPoints()). */
  const std::vector<Eigen::Vector2d>& searchPoints() const;

 private:
  sensor::Scan scan_;
  ScanForms forms_;
  double rotation_length_;
  // Built on first use; a PreparedScan belongs to one thread (tracking's).
  mutable std::shared_ptr<const plicp::ReferenceScan> reference_;
  mutable std::shared_ptr<const FacingNormals> facing_;
  mutable std::optional<std::vector<Eigen::Vector2d>> search_points_;
};

}  // namespace swslam::tracking

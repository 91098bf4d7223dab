#pragma once
// A 2D laser scan reduced to its valid rays, in the sensor frame.

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace swslam::sensor
{
/** Why rays of an observation were dropped (counts per reason). */
struct RayRejections
{
  size_t flagged_invalid = 0;  ///< validity flag false in the observation
  size_t not_finite = 0;       ///< NaN or inf range
  size_t non_positive = 0;     ///< range <= 0
  size_t below_min = 0;        ///< 0 < range < min_range
  size_t at_or_above_max = 0;  ///< range >= max_range ("no return")
  size_t total() const
  {
    return flagged_invalid + not_finite + non_positive + below_min + at_or_above_max;
  }
};

/** Valid rays of one scan, sorted by increasing angle (counter-clockwise), sensor frame.
 * All per-ray vectors have the same length. */
struct Scan
{
  std::vector<double> angles;            ///< ray angle [rad] in the sensor frame
  std::vector<double> ranges;            ///< measured range [m]
  std::vector<Eigen::Vector2d> points;   ///< ranges[i] * (cos, sin)(angles[i])
  std::vector<int> beam_index;           ///< index of the ray in the original observation

  mrpt::poses::CPose2D sensor_pose;  ///< sensor pose on the vehicle (2D projection)
  mrpt::Clock::time_point timestamp;
  std::string sensor_label;
  size_t beam_count = 0;  ///< rays in the original observation, valid or not
  double aperture = 0;    ///< field of view [rad]
  double max_range = 0;   ///< sensor maximum range [m]
  bool right_to_left = true;  ///< the observation's ray order (beamAngle)
  RayRejections rejected;

  size_t size() const { return ranges.size(); }
  bool empty() const { return ranges.empty(); }
};

/** Builds a Scan from an MRPT observation, keeping only valid rays (validity flag set,
 * finite, min_range <= r < max_range). Throws std::invalid_argument naming the problem
 * when the observation's geometry is inconsistent (fewer than 2 beams, aperture not in
 * (0, 2*pi], max range not positive and finite, more rays or a sensor pose not finite or
 * farther out than input_bounds.h allows). A scan with no valid ray is returned empty. */
Scan scanFromObservation(const mrpt::obs::CObservation2DRangeScan& obs, double min_range = 0.0);

/** The geometry checks of scanFromObservation alone (cheap: no ray is converted). */
void checkObservationGeometry(const mrpt::obs::CObservation2DRangeScan& obs);

/** scanFromObservation without the geometry checks, for an observation that has passed
 * checkObservationGeometry where it entered (SlamSystem::feed checks every input scan once). */
Scan scanFromCheckedObservation(const mrpt::obs::CObservation2DRangeScan& obs, double min_range = 0.0);

/** Angle [rad] of beam `i` of `n` over `aperture`, counter-clockwise, as MRPT defines it. */
double beamAngle(size_t i, size_t n, double aperture, bool right_to_left = true);

/** Root mean square distance of the points from the sensor [m], the length that scales
 * rotations to metres (a turn of a radians moves the points by about a times it); 1 m when
 * there are none (or all sit at the sensor). */
double rotationLength(const std::vector<Eigen::Vector2d>& points);

}  // namespace swslam::sensor

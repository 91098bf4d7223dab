#pragma once
// A Scan kept small for as long as a mission lasts: its valid rays' ranges as the observation
// held them (float) and their beam indices, 8 bytes a ray, and the scan's header. expand()
// rebuilds the Scan that scanFromCheckedObservation made, bit for bit (angles and points are
// computed from the same ranges by the same formulas and MRPT's same sine table).

#include <swslam/sensor/scan.h>

#include <cstdint>
#include <vector>

namespace swslam::sensor
{
struct CompactScan
{
  std::vector<float> ranges;
  std::vector<uint32_t> beam_index;
  mrpt::poses::CPose2D sensor_pose;
  mrpt::Clock::time_point timestamp;
  std::string sensor_label;
  size_t beam_count = 0;
  double aperture = 0;
  double max_range = 0;
  bool right_to_left = true;
  RayRejections rejected;

  size_t bytes() const
  {
    return sizeof(*this) + ranges.capacity() * sizeof(float) + beam_index.capacity() * sizeof(uint32_t) +
           sensor_label.capacity();
  }
};

/** The compact form of `scan`, a Scan made by scanFromCheckedObservation. Throws
 * std::invalid_argument if a range is not a float's value (the scan was not read from an
 * observation) or the per-ray vectors differ in length. */
CompactScan compactScan(const Scan& scan);

/** The Scan `c` was made from. */
Scan expandScan(const CompactScan& c);

}  // namespace swslam::sensor

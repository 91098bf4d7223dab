#pragma once
// A sanitized scan (sanitizedScan()) as the map keeps it for a node: what the grid insertion
// reads, and nothing else. MRPT's observation holds a float range, an int32 intensity and a
// validity byte per ray (9 bytes); the map needs the range and the validity (4 bytes and a
// bit), and never an intensity.

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

namespace swslam::map
{
class StoredScan
{
 public:
  explicit StoredScan(const mrpt::obs::CObservation2DRangeScan& scan);
  /** The scan again: every field the grid insertion reads equal to the original's, bit for
   * bit (ranges, validity, geometry, labels); no intensities. */
  mrpt::obs::CObservation2DRangeScan restore() const;
  size_t bytes() const;

 private:
  mrpt::obs::CObservation2DRangeScan header_;  ///< the scan without its rays
  std::vector<float> ranges_;
  std::vector<bool> valid_;
};

}  // namespace swslam::map

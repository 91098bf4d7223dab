#pragma once
// A log's laser scans paired with reference poses, for the benchmarks.

#include <swslam/common/tum_io.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace swslam::io
{
/** Scans of one log with the vehicle's reference pose at each. */
struct ScansWithTruth
{
  std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
  std::vector<mrpt::poses::CPose2D> truth;  ///< vehicle pose at scans[k]
  size_t skipped_without_truth = 0;
};

/** Reads the laser scans of `rawlog_path` (of one sensor: the first scan's label) and pairs
 * them with `truth`: by index when the counts match, otherwise by timestamp (closest within
 * `max_dt` seconds). Throws std::runtime_error if nothing can be paired. */
ScansWithTruth loadScansWithTruth(const std::string& rawlog_path,
                                  const std::vector<common::StampedPose>& truth, double max_dt = 0.01);

}  // namespace swslam::io

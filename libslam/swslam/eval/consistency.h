#pragma once
// Ground-truth-free check of a trajectory: how well the log's scans agree with each other at
// the trajectory's poses. For every pair of scans taken close to each other, the points of the
// later scan are placed in the earlier one's frame and scored by their distance to its local
// lines (PLICP's correspondences, doc/plicp.md), with no re-matching. Pairs far apart in time
// ("revisits") show whether places seen twice line up. Scoring two trajectories on the same
// pairs tells which of them the scans support, e.g. an estimate against a reference that is
// itself the output of another SLAM system.

#include <swslam/common/tum_io.h>
#include <swslam/io/carmen_log.h>
#include <swslam/sensor/scan.h>

#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace swslam::eval
{
struct ConsistencyOptions
{
  double radius = 3.0;        ///< [m] pairs of scans whose sensors are this close...
  size_t min_gap = 1;         ///< ...and at least this many scored scans apart (after the stride)
  size_t revisit_gap = 30;    ///< pairs this many scored scans apart are also scored as revisits
  double max_dist = 0.5;      ///< [m] a point farther from the other scan's nearest ray is unmatched
  double good_error = 0.05;   ///< [m] point-to-line errors below this count as agreeing
  double error_cap = 0.2;     ///< [m] errors enter the rms capped at this (clutter, occlusion)
  double min_segment = 0.2;   ///< [m] shortest segment defining a line ([plicp] min_segment_length)
};

/** Point-to-line errors of the matched points over a set of scan pairs. */
struct ConsistencyStats
{
  size_t pairs = 0;
  size_t points = 0;  ///< matched points (within max_dist of the other scan)
  size_t good = 0;    ///< of them, with an error below good_error (output: frac_good)
  double rms_capped = 0;  ///< [m] rms of min(error, error_cap); NaN without points
  double median = 0;      ///< [m] to 0.1 mm (a histogram); NaN without points
  double fractionGood() const;
};

struct ConsistencyResult
{
  ConsistencyStats all;       ///< every pair
  ConsistencyStats revisits;  ///< pairs at least revisit_gap scans apart
};

/** Pairs (i, j), i < j, j - i >= min_gap, of positions within `radius` of each other, in
 * increasing (i, j). */
std::vector<std::pair<size_t, size_t>> nearbyPairs(const std::vector<mrpt::poses::CPose2D>& poses,
                                                   double radius, size_t min_gap);

/** Scores `scans` (points in their sensor frames) placed at `sensor_poses` (one per scan) on
 * `pairs` (from nearbyPairs()). Throws std::invalid_argument if the sizes differ or a pair
 * indexes past the scans. */
ConsistencyResult scanConsistency(const std::vector<sensor::Scan>& scans,
                                  const std::vector<mrpt::poses::CPose2D>& sensor_poses,
                                  const std::vector<std::pair<size_t, size_t>>& pairs,
                                  const ConsistencyOptions& options);

/** A log's scans with a pose of every trajectory, associated by timestamp. */
struct PosedScans
{
  std::vector<sensor::Scan> scans;  ///< every `stride`-th scan that all trajectories have a pose for
  /** per trajectory, the sensor pose (vehicle pose (+) the scan's sensor pose) of each scan */
  std::vector<std::vector<mrpt::poses::CPose2D>> sensor_poses;
  size_t log_scans = 0;  ///< scans read from the log
  size_t unposed = 0;    ///< of them, without a pose within max_dt in some trajectory
};

/** Reads the scans of `log_path` (rawlog, or CARMEN log read with `carmen`, as swslam reads
 * it; rays shorter than `min_range` dropped; only the scans of `sensor_label`, or of the first
 * sensor seen if empty) and associates each with the pose of each trajectory closest in time,
 * within `max_dt` seconds. Keeps every `stride`-th associated scan (long runs: pass their
 * keyframes, or a stride). Throws std::runtime_error naming the problem if the log cannot be
 * read or fewer than two scans associate. */
PosedScans loadPosedScans(const std::string& log_path,
                          const std::vector<std::vector<common::StampedPose>>& trajectories,
                          double max_dt, size_t stride, double min_range,
                          const io::CarmenParams& carmen, const std::string& sensor_label = "");

/** What `swslam-eval consistency` prints: reads the log, picks the pairs on the first
 * trajectory and scores every trajectory on them (`names` label them). */
std::string consistencyReport(const std::string& log_path, const std::vector<std::string>& names,
                              const std::vector<std::vector<common::StampedPose>>& trajectories,
                              const ConsistencyOptions& options, double max_dt, size_t stride,
                              double min_range, const io::CarmenParams& carmen,
                              const std::string& sensor_label = "");

/** "key=value" lines for one trajectory's result (`trajectory=name`, then `all_*` and
 * `revisit_*`), then a '#' line for a human reader. */
std::string formatConsistency(const std::string& name, const ConsistencyResult& r,
                              const ConsistencyOptions& options);

}  // namespace swslam::eval

#pragma once
// CARMEN log -> observation-only MRPT rawlog (+ TUM reference trajectory), the library
// side of swslam-carmen2rawlog.

#include <swslam/io/carmen_log.h>

#include <string>

namespace swslam::io
{
struct Carmen2RawlogOptions
{
  std::string input;             ///< CARMEN log, plain or .gz
  std::string output;            ///< rawlog to write (gzip-compressed)
  std::string ground_truth;      ///< TUM file of the scans' reference poses; empty: none
  int compress_level = 5;        ///< gzip level of the rawlog, 0-9
  /** Before each scan with a reference pose, a CObservationOdometry holding that pose, at the
   * scan's timestamp (label "REFERENCE_ODOMETRY"): a perfect motion prediction, to measure how
   * far the laser alone takes a run from the reference (doc/evaluation.md). It is the reference,
   * never an input to judge a run by. Needs params.laser_only (the ODOM lines would mix in) and
   * params.repair_timestamps (a reader drops a reading older than the one before). */
  bool reference_odometry = false;
  CarmenParams params;
};

/** Converts, writing both outputs atomically. If the input's gzip stream is cut short or
 * corrupt, the lines before are converted and written, and the returned stats' `damage` says
 * where it stopped. Throws std::runtime_error naming the problem if the input cannot be read
 * or holds no laser scan (nothing is written then), and
 * std::invalid_argument for a compress level outside 0-9 or reference_odometry without
 * params.laser_only and params.repair_timestamps. */
CarmenStats carmen2rawlog(const Carmen2RawlogOptions& opts,
                          CarmenLogReader::WarningSink warn = {});

}  // namespace swslam::io

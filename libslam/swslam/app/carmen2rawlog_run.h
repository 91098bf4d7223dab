#pragma once
// The `swslam-carmen2rawlog` program: a CARMEN log converted to an observation-only MRPT rawlog
// and its reference poses (io/carmen2rawlog.h, doc/carmen.md), existing outputs kept unless
// told otherwise. The options are plain values: the program's executable fills them without
// loading the library.

#include <iosfwd>
#include <string>

namespace swslam::app
{
struct Carmen2RawlogRunOptions
{
  std::string input;         ///< CARMEN log, plain or .gz
  std::string output;        ///< rawlog to write
  std::string ground_truth;  ///< TUM file of the scans' reference poses; empty: none
  int compress_level = 5;    ///< gzip level of the rawlog, 0-9
  double max_range = 0;      ///< [m] if > 0: every laser's maximum range; 0: from the log
  bool laser_only = false;   ///< drop the odometry
  bool repair_timestamps = false;   ///< make each stream's timestamps strictly increasing
  bool reference_odometry = false;  ///< each scan's reference pose as odometry before it
  bool quiet = false;        ///< print no warnings, only the summary
  bool overwrite = false;    ///< replace existing outputs (else they are an error)
};

/** Runs; prints what it wrote and the log's figures to `out`, warnings to `err`. Returns 0; 2
 * if the log's gzip stream broke off (what was before it is written, the damage printed to
 * `err`); 1 after printing the problem to `err` for bad options or an unusable input (nothing
 * written). */
int runCarmen2Rawlog(const Carmen2RawlogRunOptions& opts, std::ostream& out, std::ostream& err);

}  // namespace swslam::app

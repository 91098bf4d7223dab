#pragma once
// How a run folder was made: run.ini, written beside a run's other outputs (run_outputs.h).
// It names the program and its version, the input and the options that change the result,
// and holds the whole configuration the run used, every key of both tiers, so that the run
// can be repeated, or its map rebuilt (swslam-regen-map -r RUN), with no flag repeated.
//
//   [run]
//   program = swslam
//   version = 0.1.0
//   input = /data/valley.rawlog      (absolute; swslam-live: its recording)
//   odometry = true
//   ...
//   [tracking]                       (every section of app::Config, every key)
//   ...

#include <swslam/app/config.h>

#include <cstddef>
#include <string>

namespace swslam::app
{
struct RunRecord
{
  std::string program;  ///< swslam, swslam-live
  std::string version = swslamVersion();
  std::string input;    ///< the log the run read, absolute
  bool use_odometry = true;
  bool deterministic = false;
  std::string sensor_label, scan_topic, odom_topic;  ///< empty: the program chose
  size_t max_scans = 0;       ///< 0: all
  size_t throttle_scans = 1;  ///< one scan in this many
  Config config;

  /** The project's version (CMake's project version). */
  static std::string swslamVersion();
};

/** run.ini's text for `r`. */
std::string runRecordText(const RunRecord& r);

/** Reads a run.ini. Throws std::invalid_argument naming `path` and the problem: a missing
 * file, a missing [run] section or key, a value that is not what the key holds, a config key
 * that is unknown or out of range. */
RunRecord readRunRecord(const std::string& path);

/** The file name run.ini, for the lists of a run's outputs. */
inline constexpr const char* kRunRecordFile = "run.ini";

}  // namespace swslam::app

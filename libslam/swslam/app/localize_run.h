#pragma once
// The `swslam-localize` program (doc/localization.md): a log localized on a saved map (a
// session or a run folder), the map and its graph fixed. The options are plain values: the
// program's executable fills them without loading the library.

#include <array>
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>

namespace swslam::app
{
struct LocalizeOptions
{
  std::string map;     ///< a saved session or a swslam run folder
  std::string input;   ///< the log to localize
  std::string output;  ///< output folder (created if missing)
  std::string config;  ///< .ini; empty: the map's own run.ini
  bool use_odometry = true;
  std::string sensor_label, scan_topic, odom_topic;  ///< as swslam's
  /** Vehicle pose [x m, y m, yaw deg] of the first scan in the map frame; none: relocalize. */
  std::optional<std::array<double, 3>> initial_pose;
  size_t max_scans = 0;  ///< stop after this many scans; 0: all
};

/** Runs; prints the summary to `out`, problems to `err`. Exit codes as app/exit_codes.h; no
 * scan localized at all is kExitInputError (a log of another place, or a map not covering it),
 * with every output written. */
int runLocalize(const LocalizeOptions& opts, std::ostream& out, std::ostream& err);

}  // namespace swslam::app

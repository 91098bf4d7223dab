#pragma once
// The `swslam` application: replays a rawlog, CARMEN log or ROS bag through the SLAM system and writes
// every output. Lives in the library so that tests run exactly what the app runs.

#include <swslam/app/exit_codes.h>

#include <iosfwd>
#include <string>

namespace swslam::app
{
struct OfflineRunOptions
{
  std::string config;        ///< .ini; empty: the installed config/default.ini (default_config.h)
  std::string input;         ///< rawlog, CARMEN log (.log, .log.gz, .clf) or ROS 1 bag
  std::string output;        ///< output directory (created if missing)
  std::string ground_truth;  ///< TUM file for ATE/RPE; empty: none
  bool deterministic = false;
  bool use_odometry = true;
  std::string sensor_label;  ///< empty: the first laser in the log
  std::string scan_topic;    ///< bags: the LaserScan topic; empty: the only one
  std::string odom_topic;    ///< bags: the Odometry topic; empty: the only one, if any
  bool progress = true;      ///< progress bar (drawn only on a terminal)
  bool render = true;        ///< render.png
  size_t max_scans = 0;      ///< stop after this many scans; 0: all
  size_t throttle_scans = 1;  ///< use one scan in this many (io::ThrottledScanSource); 1: all
  double realtime_factor = 0;  ///< > 0: replay paced at this multiple of the log's own rate
  std::string resume;        ///< a saved session to continue (app/session.h); its config is the run's
  std::string save_session;  ///< where to save this run as a session; empty: not saved
};

/** Runs; prints the Table I summary to `out`, warnings and the progress bar to stderr. */
int runOffline(const OfflineRunOptions& opts, std::ostream& out, std::ostream& err);

}  // namespace swslam::app

#pragma once
// Parameters of the system as a whole (how the three modules run), section [system].

#include <swslam/common/param_table.h>

namespace swslam::system
{
/** Section [system]: declared in table() (options.cpp). */
struct SystemOptions
{
  int input_queue_capacity = 200;  ///< threaded mode: scans waiting for tracking at most (feed() waits)
  bool final_full_optimization = true;  ///< optimize the whole graph once the input ends
  int max_printed_warnings = 10;   ///< skipped-scan messages printed per kind; all are counted
  int timestamp_resume_scans = 5;  ///< this many scans in order behind the last taken one resume the log (0: never)
  /// [s] a scan whose stamp equals the latest taken, or is at most this before it, is taken under
  /// its own stamp (a logger's jitter: Intel's raw log repeats or steps back 631 stamps); further
  /// back, skipped as not increasing (0: only increasing stamps are taken)
  double timestamp_step_back = 1.0;
  /// threaded mode: keyframes the graph thread has not finished at most when tracking takes a
  /// scan (it waits until then); 0: tracking goes on from optimized keyframes; -1: no bound
  int max_graph_lag = 0;
  /// [m/s] an odometry increment longer than this speed times the time since the previous
  /// scan (at least one second's worth) is dropped and said, not fed to tracking (0: no check)
  double max_odometry_speed = 50;

  static const common::ParamTable<SystemOptions>& table();
};

}  // namespace swslam::system

#pragma once
// The `swslam-live` application: scans from a Hokuyo (MRPT's CHokuyoURG, serial or Ethernet)
// into the same three-thread system as `swslam`, or with --localize localized on a saved map
// as `swslam-localize` does, recorded to a rawlog as they arrive, with the outputs written
// periodically and on SIGINT/SIGTERM (doc/live.md).

#include <iosfwd>
#include <string>

namespace swslam::app
{
struct LiveRunOptions
{
  std::string config;                  ///< swslam sections (empty: the installed default.ini;
                                       ///< with `localize`, the map's run.ini)...
  std::string sensor_config;           ///< ...and an MRPT rawlog-grabber .ini with the sensor
                                       ///< section (empty: the sensor section is in `config`)
  std::string sensor_section = "LASER_2D";
  std::string output;                  ///< output directory (created if missing)
  std::string record;                  ///< rawlog to record into; empty: OUTPUT/recording.rawlog
  bool deterministic = false;          ///< the system on the reading thread (replays identically)
  double save_period = 30;             ///< [s] outputs rewritten this often (0: only at the end)
  double duration = 0;                 ///< [s] stop after this long (0: until SIGINT/SIGTERM)
  double stall_timeout = 2;            ///< [s] no scan this long: the sensor stopped answering
  bool status = true;                  ///< status line in place on a terminal, else a line every 10 s; false: none
  bool render = true;
  /** A saved session or run folder to localize on (doc/localization.md): no mapping, the
   * outputs are swslam-localize's. Empty: map. */
  std::string localize;
};

/** Runs until the duration ends or a signal arrives; returns 0 on a clean stop (signal or
 * duration), 1 for a bad config, 2 if not one scan arrived (the sensor never answered:
 * nothing is written, the empty recording removed), 3 if a module failed, 4 if an output
 * could not be written. */
int runLive(const LiveRunOptions& opts, std::ostream& out, std::ostream& err);

}  // namespace swslam::app

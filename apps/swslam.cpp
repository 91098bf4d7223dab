// swslam: sliding-window 2D LiDAR SLAM on a rawlog, CARMEN log, ROS 1 or ROS 2 bag (see README and doc/system.md).
#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

#include <iostream>

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam: robust sliding-window 2D LiDAR SLAM (offline replay)", ' ', "0.1");
  TCLAP::ValueArg<std::string> config("c", "config", "Configuration (.ini; default: the installed config/default.ini)",
                                      false, "", "INI", cmd);
  TCLAP::ValueArg<std::string> input("i", "input", "MRPT rawlog, CARMEN log (.log, .log.gz, .clf), ROS 1 bag (.bag) or ROS 2 bag (rosbag2 folder, .mcap, .db3)",
                                     true, "", "LOG", cmd);
  TCLAP::ValueArg<std::string> output("o", "output", "Output directory (created if missing)", true, "",
                                      "DIR", cmd);
  TCLAP::ValueArg<std::string> gt("g", "ground-truth", "Reference trajectory (TUM) for ATE/RPE", false,
                                  "", "GT.tum", cmd);
  TCLAP::ValueArg<std::string> label("", "sensor-label", "Use only scans of this sensor", false, "",
                                     "LABEL", cmd);
  TCLAP::ValueArg<std::string> scan_topic("", "scan-topic", "Bags: the sensor_msgs/LaserScan topic (default: the only one)",
                                          false, "", "TOPIC", cmd);
  TCLAP::ValueArg<std::string> odom_topic("", "odom-topic", "Bags: the nav_msgs/Odometry topic (default: the only one, if any)",
                                          false, "", "TOPIC", cmd);
  TCLAP::ValueArg<long long> max_scans("", "max-scans", "Stop after N scans (0: all)", false, 0, "N", cmd);
  TCLAP::ValueArg<long long> throttle("", "throttle-scans",
                                   "Use one scan in N (the first, then every Nth; the odometry of those left out is kept)",
                                   false, 1, "N", cmd);
  TCLAP::ValueArg<double> rate("", "realtime-factor", "Pace the replay at this multiple of the log's rate (0: as fast as possible)",
                               false, 0, "X", cmd);
  TCLAP::ValueArg<std::string> resume("", "resume", "Continue the session saved in DIR (its configuration; no -c)",
                                      false, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> save_session("", "save-session", "Save the run as a session in DIR, to --resume later",
                                            false, "", "DIR", cmd);
  TCLAP::SwitchArg deterministic("d", "deterministic", "One thread, fixed order: repeatable results", cmd);
  TCLAP::SwitchArg no_odometry("", "no-odometry", "Ignore odometry in the log (laser only)", cmd);
  TCLAP::SwitchArg no_progress("q", "quiet", "No progress (a bar on a terminal, else a line every 10%)", cmd);
  TCLAP::SwitchArg no_render("", "no-render", "Skip render.png (no OpenGL needed)", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

  swslam::app::OfflineRunOptions o;
  o.config = config.getValue();
  o.input = input.getValue();
  o.output = output.getValue();
  o.ground_truth = gt.getValue();
  o.sensor_label = label.getValue();
  o.scan_topic = scan_topic.getValue();
  o.odom_topic = odom_topic.getValue();
  try
  {
    o.max_scans = swslam::cli::count(max_scans, 0);
    o.throttle_scans = swslam::cli::count(throttle, 1);
  }
  catch (const std::invalid_argument& e)
  {
    std::cerr << "swslam: " << e.what() << "\n";
    return 1;
  }
  o.realtime_factor = rate.getValue();
  o.deterministic = deterministic.getValue();
  o.use_odometry = !no_odometry.getValue();
  o.progress = !no_progress.getValue();
  o.render = !no_render.getValue();
  o.resume = resume.getValue();
  o.save_session = save_session.getValue();
  return SWSLAM_RUN_IN_LIBRARY("swslam", swslam_run_offline, o);
}

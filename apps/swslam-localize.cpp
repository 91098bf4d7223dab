// swslam-localize: a log localized on a saved map (doc/localization.md).
#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

#include <array>
#include <cmath>
#include <iostream>
#include <sstream>

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-localize: a log localized on a saved map, the map fixed", ' ', "0.1");
  TCLAP::ValueArg<std::string> map("m", "map", "A saved session (--save-session) or a swslam run folder", true, "",
                                   "DIR", cmd);
  TCLAP::ValueArg<std::string> input("i", "input", "Log to localize (rawlog, CARMEN log, ROS 1 or ROS 2 bag)", true,
                                     "", "LOG", cmd);
  TCLAP::ValueArg<std::string> output("o", "output", "Output folder (created if missing)", true, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> config("c", "config", "Configuration (default: the map's own run.ini)", false, "",
                                      "INI", cmd);
  TCLAP::ValueArg<std::string> initial("", "initial-pose",
                                       "First scan's vehicle pose on the map, \"X Y YAW_DEG\" (default: relocalize)",
                                       false, "", "\"X Y YAW\"", cmd);
  TCLAP::SwitchArg no_odometry("", "no-odometry", "Ignore the log's odometry", cmd);
  TCLAP::ValueArg<std::string> sensor("", "sensor", "Use only scans of this sensor label", false, "", "LABEL", cmd);
  TCLAP::ValueArg<std::string> scan_topic("", "scan-topic", "Bags: the LaserScan topic", false, "", "TOPIC", cmd);
  TCLAP::ValueArg<std::string> odom_topic("", "odom-topic", "Bags: the Odometry topic", false, "", "TOPIC", cmd);
  TCLAP::ValueArg<long long> max_scans("", "max-scans", "Stop after this many scans (0: all)", false, 0, "N", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

  swslam::app::LocalizeOptions o;
  o.map = map.getValue();
  o.input = input.getValue();
  o.output = output.getValue();
  o.config = config.getValue();
  o.use_odometry = !no_odometry.getValue();
  o.sensor_label = sensor.getValue();
  o.scan_topic = scan_topic.getValue();
  o.odom_topic = odom_topic.getValue();
  try
  {
    o.max_scans = swslam::cli::count(max_scans, 0);
  }
  catch (const std::invalid_argument& e)
  {
    std::cerr << "swslam-localize: " << e.what() << "\n";
    return 1;
  }
  if (initial.isSet())
  {
    std::istringstream s(initial.getValue());
    std::array<double, 3> p{};
    std::string rest;
    if (!(s >> p[0] >> p[1] >> p[2]) || (s >> rest) || !std::isfinite(p[0] + p[1] + p[2]))
    {
      std::cerr << "swslam-localize: --initial-pose \"" << initial.getValue()
                << "\": three finite numbers are needed, X Y YAW_DEG\n";
      return 1;
    }
    o.initial_pose = p;
  }
  return SWSLAM_RUN_IN_LIBRARY("swslam-localize", swslam_run_localize, o);
}

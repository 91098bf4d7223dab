// swslam-rawlog2bag: MRPT rawlog -> ROS 1 or ROS 2 bag (LaserScan, Odometry, the scanner's
// mounting on /tf_static), e.g. to replay a simulated dataset in ROS tools or through swslam's
// bag input.

#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-rawlog2bag: MRPT rawlog -> ROS 1 bag (out.bag) or ROS 2 bag (a rosbag2 folder of "
                     "metadata.yaml and one .mcap file, or out.mcap alone)",
                     ' ', "0.1");
  TCLAP::ValueArg<std::string> in("i", "input", "Input rawlog", true, "", "in.rawlog", cmd);
  TCLAP::ValueArg<std::string> out("o", "output",
                                    "Output bag: a name ending in .bag is a ROS 1 bag, in .mcap a single ROS 2 .mcap "
                                    "file, any other a rosbag2 folder (unless --format says)",
                                    true, "", "out.bag|out.mcap|FOLDER", cmd);
  TCLAP::ValueArg<std::string> format("", "format", "ros1 or ros2, whatever the output's name", false, "",
                                      "ros1|ros2", cmd);
  TCLAP::ValueArg<std::string> label("", "sensor-label", "Convert only scans of this sensor (default: the first)",
                                     false, "", "LABEL", cmd);
  TCLAP::ValueArg<std::string> scan_topic("", "scan-topic", "Topic of the scans", false, "/scan", "TOPIC", cmd);
  TCLAP::ValueArg<std::string> odom_topic("", "odom-topic", "Topic of the odometry", false, "/odom", "TOPIC", cmd);
  TCLAP::ValueArg<std::string> base_frame("", "base-frame", "The vehicle's frame (odometry child frame)", false,
                                          "base_link", "FRAME", cmd);
  TCLAP::ValueArg<std::string> compression("", "compression", "ROS 1 chunk compression: none, bz2 or lz4 (ROS 2: none)", false, "none",
                                           "none|bz2|lz4", cmd);
  TCLAP::SwitchArg overwrite("w", "overwrite", "Overwrite an existing output", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

  swslam::app::Rawlog2BagRunOptions o;
  o.conversion.input = in.getValue();
  o.conversion.output = out.getValue();
  o.conversion.format = format.getValue();
  o.conversion.sensor_label = label.getValue();
  o.conversion.scan_topic = scan_topic.getValue();
  o.conversion.odom_topic = odom_topic.getValue();
  o.conversion.base_frame = base_frame.getValue();
  o.conversion.compression = compression.getValue();
  o.overwrite = overwrite.getValue();
  return SWSLAM_RUN_IN_LIBRARY("swslam-rawlog2bag", swslam_run_rawlog2bag, o);
}

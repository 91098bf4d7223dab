// swslam-rawlog2bag: MRPT rawlog -> ROS 1 bag (LaserScan, Odometry, the scanner's mounting on
// /tf_static), e.g. to replay a simulated dataset in ROS tools or through swslam's bag input.

#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-rawlog2bag: MRPT rawlog -> ROS 1 bag", ' ', "0.1");
  TCLAP::ValueArg<std::string> in("i", "input", "Input rawlog", true, "", "in.rawlog", cmd);
  TCLAP::ValueArg<std::string> out("o", "output", "Output bag", true, "", "out.bag", cmd);
  TCLAP::ValueArg<std::string> label("", "sensor-label", "Convert only scans of this sensor (default: the first)",
                                     false, "", "LABEL", cmd);
  TCLAP::ValueArg<std::string> scan_topic("", "scan-topic", "Topic of the scans", false, "/scan", "TOPIC", cmd);
  TCLAP::ValueArg<std::string> odom_topic("", "odom-topic", "Topic of the odometry", false, "/odom", "TOPIC", cmd);
  TCLAP::ValueArg<std::string> base_frame("", "base-frame", "The vehicle's frame (odometry child frame)", false,
                                          "base_link", "FRAME", cmd);
  TCLAP::ValueArg<std::string> compression("", "compression", "Chunk compression: none, bz2 or lz4", false, "none",
                                           "none|bz2|lz4", cmd);
  TCLAP::SwitchArg overwrite("w", "overwrite", "Overwrite an existing output", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

  swslam::app::Rawlog2BagRunOptions o;
  o.conversion.input = in.getValue();
  o.conversion.output = out.getValue();
  o.conversion.sensor_label = label.getValue();
  o.conversion.scan_topic = scan_topic.getValue();
  o.conversion.odom_topic = odom_topic.getValue();
  o.conversion.base_frame = base_frame.getValue();
  o.conversion.compression = compression.getValue();
  o.overwrite = overwrite.getValue();
  return SWSLAM_RUN_IN_LIBRARY("swslam-rawlog2bag", swslam_run_rawlog2bag, o);
}

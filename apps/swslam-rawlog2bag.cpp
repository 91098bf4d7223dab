// swslam-rawlog2bag: MRPT rawlog -> ROS 1 bag (LaserScan, Odometry, the scanner's mounting on
// /tf_static), e.g. to replay a simulated dataset in ROS tools or through swslam's bag input.

#include "cli.h"
#include <swslam/io/rawlog2bag.h>

#include <filesystem>
#include <iostream>

int main(int argc, char** argv)
{
  try
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

    if (std::filesystem::exists(out.getValue()) && !overwrite.getValue())
      throw std::runtime_error("'" + out.getValue() + "' exists (use -w to overwrite)");
    swslam::io::Rawlog2BagOptions opts;
    opts.input = in.getValue();
    opts.output = out.getValue();
    opts.sensor_label = label.getValue();
    opts.scan_topic = scan_topic.getValue();
    opts.odom_topic = odom_topic.getValue();
    opts.base_frame = base_frame.getValue();
    opts.compression = compression.getValue();
    const auto stats = swslam::io::rawlog2bag(opts);
    std::cout << "wrote " << opts.output << "\n" << swslam::io::formatRawlog2BagStats(stats, opts);
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "swslam-rawlog2bag: " << e.what() << "\n";
    return 1;
  }
}

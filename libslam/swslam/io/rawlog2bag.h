#pragma once
// MRPT rawlog -> ROS 1 or ROS 2 bag, the library side of swslam-rawlog2bag: the scans of one
// sensor as sensor_msgs/LaserScan, the odometry as nav_msgs/Odometry, the scanner's pose on
// the vehicle as a /tf_static transform, each message at its own timestamp. A ROS 2 bag is a
// rosbag2 folder (metadata.yaml and one .mcap file) or a single .mcap file
// (ros2_bag_writer.h). What BagReader and Ros2BagReader read back is what the rawlog held
// (tests/bag_test.sh and tests/ros2_bag_test.sh run swslam on each).

#include <map>
#include <string>

namespace swslam::io
{
struct Rawlog2BagOptions
{
  std::string input;                   ///< rawlog (either format, plain or gzip)
  std::string output;                  ///< bag to write: X.bag, X.mcap or a rosbag2 folder
  /** "ros1", "ros2" or "" (by the output's name: ROS 1 if it ends in .bag, else ROS 2: a single
   * file if it ends in .mcap, else a rosbag2 folder). */
  std::string format;
  std::string scan_topic = "/scan";
  std::string odom_topic = "/odom";
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";  ///< the odometry's child frame, parent of the scans' frame
  std::string sensor_label;            ///< only scans of this sensor; empty: the first one seen
  std::string compression = "none";    ///< of a ROS 1 bag's chunks: none, bz2 or lz4 (ROS 2: none)
};

struct Rawlog2BagStats
{
  std::string sensor_label;  ///< the scans' sensor, also their frame id
  size_t scans = 0;
  size_t odometry = 0;       ///< readings, and rawlog actions (integrated into a pose)
  std::map<std::string, size_t> other_labels;  ///< scans of other sensors, skipped
  size_t other_observations = 0;               ///< neither scans nor odometry, skipped
};

/** Converts, writing the bag atomically (a rosbag2 folder beside its name, then renamed).
 * Throws std::runtime_error naming the problem if the input cannot be read, holds no scan of
 * the sensor, or a scan or reading has no timestamp, or the output is a folder that is not a
 * rosbag2 one (nothing is written then); std::invalid_argument for an unknown format or
 * compression, or a compression for a ROS 2 bag. */
Rawlog2BagStats rawlog2bag(const Rawlog2BagOptions& opts);

std::string formatRawlog2BagStats(const Rawlog2BagStats& stats, const Rawlog2BagOptions& opts);

}  // namespace swslam::io

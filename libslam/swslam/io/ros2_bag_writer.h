#pragma once
// A ROS 2 bag written: a rosbag2 folder (metadata.yaml and one .mcap file, storage "mcap", as
// `ros2 bag record` writes from Iron on) or a single .mcap file, of sensor_msgs/msg/LaserScan,
// nav_msgs/msg/Odometry and tf2_msgs/msg/TFMessage messages in CDR (ros2_messages.h) with
// their ros2msg definitions; /tf_static offered as latched (transient local), as REP 105
// wants. What Ros2BagReader reads back is what was written.

#include <swslam/io/mcap_writer.h>

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace swslam::io
{
class Ros2BagWriter
{
 public:
  /** Writes into `path`: a folder to create (metadata.yaml and <name>_0.mcap, `name` the
   * folder's final name) if `folder`, else the .mcap file itself. Throws std::runtime_error. */
  Ros2BagWriter(const std::string& path, bool folder, const std::string& name);

  void write(const std::string& topic, uint64_t time_ns, const sensor_msgs::LaserScan& m);
  void write(const std::string& topic, uint64_t time_ns, const nav_msgs::Odometry& m);
  void write(const std::string& topic, uint64_t time_ns, const tf2_msgs::TFMessage& m);

  /** Ends the .mcap file, then writes metadata.yaml (a folder). Throws std::runtime_error. */
  void close();

 private:
  struct Topic
  {
    std::string type;
    uint16_t channel = 0;
    uint64_t messages = 0;
  };
  void write(const std::string& topic, const std::string& type, uint64_t time_ns, const std::vector<uint8_t>& cdr);

  std::string path_, file_name_;
  bool folder_;
  McapWriter mcap_;
  std::map<std::string, uint16_t> schemas_;  ///< by type
  std::map<std::string, Topic> topics_;
  uint64_t first_ = 0, last_ = 0, messages_ = 0;
};

/** Whether swslam-rawlog2bag writes a ROS 2 bag to `output` when no format is asked for: a
 * name ending in .mcap (the file alone) or not in .bag (a rosbag2 folder). */
bool isRos2Output(const std::string& output);

}  // namespace swslam::io

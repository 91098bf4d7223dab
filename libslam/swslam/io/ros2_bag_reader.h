#pragma once
// Streaming reader of ROS 2 bags (ros2_storage.h: a rosbag2 folder of .db3 or .mcap files, a
// single .mcap or .db3): what BagReader does for ROS 1 bags, for the ROS 2 types. The
// sensor_msgs/msg/LaserScan messages of one topic become CObservation2DRangeScan (labelled
// with the topic), the nav_msgs/msg/Odometry messages of one topic CObservationOdometry, the
// scanner's pose the /tf_static (tf2_msgs/msg/TFMessage) transform from the odometry's child
// frame (base_link without odometry) to the scans' frame. The CDR is decoded into the ROS 1
// message structs (ros2_messages.h) and converted by ros_conversion.h, so the same messages
// give the same observations in both formats.

#include <swslam/io/bag_reader.h>
#include <swslam/io/ros2_storage.h>

#include <memory>
#include <string>

namespace swslam::io
{
class Ros2BagReader : public BagReaderBase
{
 public:
  /** The name of the format, for the run's report. */
  static constexpr const char* kFormat = "ROS 2 bag";
  static constexpr const char* kScanType = "sensor_msgs/msg/LaserScan";

  /** Opens the bag and picks its topics, as BagReader does (the same errors, with the ROS 2
   * type names), or throws std::runtime_error naming what openRos2Storage could not open.
   * Messages come in the storage's order: timestamps for .db3, the file's for .mcap. */
  Ros2BagReader(const std::string& path, const BagReaderOptions& opts);

 private:
  void findSensorPose();
  /** The first message of `topic` (false if none). */
  bool first(const std::string& topic, Ros2Message& out);
  void readSameTime() override;

  std::unique_ptr<Ros2Storage> storage_;
  std::unique_ptr<Ros2Message> lookahead_;  ///< read, of the next time
};

}  // namespace swslam::io

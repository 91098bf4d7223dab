#include <swslam/io/ros2_bag_writer.h>

#include <swslam/common/atomic_file.h>
#include <swslam/io/ros2_messages.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace swslam::io
{
namespace
{
// The ros2msg definitions, each followed by those of the types it uses (as rosbag2 writes them).
const char* const kHeader = "builtin_interfaces/Time stamp\nstring frame_id\n";
const char* const kTime = "int32 sec\nuint32 nanosec\n";
const char* const kVector3 = "float64 x\nfloat64 y\nfloat64 z\n";
const char* const kQuaternion = "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n";

std::string definition(const std::string& main, const std::vector<std::pair<std::string, std::string>>& uses)
{
  std::string d = main;
  for (const auto& [type, text] : uses) d += std::string(80, '=') + "\nMSG: " + type + "\n" + text;
  return d;
}

std::string definitionOf(const std::string& type)
{
  if (type == "sensor_msgs/msg/LaserScan")
    return definition("std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\n"
                      "float32 time_increment\nfloat32 scan_time\nfloat32 range_min\nfloat32 range_max\n"
                      "float32[] ranges\nfloat32[] intensities\n",
                      {{"std_msgs/Header", kHeader}, {"builtin_interfaces/Time", kTime}});
  if (type == "nav_msgs/msg/Odometry")
    return definition(
        "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
        "geometry_msgs/TwistWithCovariance twist\n",
        {{"std_msgs/Header", kHeader},
         {"builtin_interfaces/Time", kTime},
         {"geometry_msgs/PoseWithCovariance", "geometry_msgs/Pose pose\nfloat64[36] covariance\n"},
         {"geometry_msgs/Pose", "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n"},
         {"geometry_msgs/Point", kVector3},
         {"geometry_msgs/Quaternion", kQuaternion},
         {"geometry_msgs/TwistWithCovariance", "geometry_msgs/Twist twist\nfloat64[36] covariance\n"},
         {"geometry_msgs/Twist", "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n"},
         {"geometry_msgs/Vector3", kVector3}});
  return definition(
      "geometry_msgs/TransformStamped[] transforms\n",
      {{"geometry_msgs/TransformStamped",
        "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/Transform transform\n"},
       {"std_msgs/Header", kHeader},
       {"builtin_interfaces/Time", kTime},
       {"geometry_msgs/Transform", "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n"},
       {"geometry_msgs/Vector3", kVector3},
       {"geometry_msgs/Quaternion", kQuaternion}});
}

/** The QoS rosbag2 records /tf_static with: reliable, transient local (latched), keep last. */
const char* const kLatchedQos =
    "- history: 1\n  depth: 1\n  reliability: 1\n  durability: 1\n  deadline:\n    sec: 9223372036\n"
    "    nsec: 854775807\n  lifespan:\n    sec: 9223372036\n    nsec: 854775807\n  liveliness: 1\n"
    "  liveliness_lease_duration:\n    sec: 9223372036\n    nsec: 854775807\n"
    "  avoid_ros_namespace_conventions: false\n";

std::string mcapPath(const std::string& path, bool folder, const std::string& name)
{
  if (!folder) return path;
  std::filesystem::create_directories(path);
  return path + "/" + name + "_0.mcap";
}

/** A YAML double-quoted string. */
std::string quoted(const std::string& s)
{
  std::string q = "\"";
  for (const char c : s)
  {
    if (c == '"' || c == '\\') q += '\\';
    if (c == '\n')
      q += "\\n";
    else
      q += c;
  }
  return q + "\"";
}
}  // namespace

bool isRos2Output(const std::string& output)
{
  const std::string ext = std::filesystem::path(output).extension().string();
  return ext != ".bag";
}

Ros2BagWriter::Ros2BagWriter(const std::string& path, bool folder, const std::string& name)
    : path_(path),
      file_name_(name + "_0.mcap"),
      folder_(folder),
      mcap_(mcapPath(path, folder, name), "ros2", "swslam-rawlog2bag")
{
}

void Ros2BagWriter::write(const std::string& topic, uint64_t t, const sensor_msgs::LaserScan& m)
{
  write(topic, "sensor_msgs/msg/LaserScan", t, laserScanCdr(m));
}
void Ros2BagWriter::write(const std::string& topic, uint64_t t, const nav_msgs::Odometry& m)
{
  write(topic, "nav_msgs/msg/Odometry", t, odometryCdr(m));
}
void Ros2BagWriter::write(const std::string& topic, uint64_t t, const tf2_msgs::TFMessage& m)
{
  write(topic, "tf2_msgs/msg/TFMessage", t, tfMessageCdr(m));
}

void Ros2BagWriter::write(const std::string& topic, const std::string& type, uint64_t time_ns,
                          const std::vector<uint8_t>& cdr)
{
  auto [it, added] = topics_.try_emplace(topic);
  Topic& t = it->second;
  if (added)
  {
    auto schema = schemas_.find(type);
    if (schema == schemas_.end()) schema = schemas_.emplace(type, mcap_.addSchema(type, "ros2msg", definitionOf(type))).first;
    t.type = type;
    t.channel = mcap_.addChannel(schema->second, topic, "cdr",
                                 {{"offered_qos_profiles", topic == "/tf_static" ? kLatchedQos : ""}});
  }
  else if (t.type != type)
    throw std::logic_error("topic '" + topic + "' written as " + type + " and " + t.type);
  mcap_.write(t.channel, time_ns, cdr);
  t.messages++;
  first_ = messages_ == 0 ? time_ns : std::min(first_, time_ns);
  last_ = std::max(last_, time_ns);
  messages_++;
}

void Ros2BagWriter::close()
{
  mcap_.close();
  if (!folder_) return;
  std::ostringstream y;
  y << "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: mcap\n  duration:\n    nanoseconds: "
    << last_ - first_ << "\n  starting_time:\n    nanoseconds_since_epoch: " << first_
    << "\n  message_count: " << messages_ << "\n  topics_with_message_count:\n";
  for (const auto& [name, t] : topics_)
    y << "    - topic_metadata:\n        name: " << name << "\n        type: " << t.type
      << "\n        serialization_format: cdr\n        offered_qos_profiles: "
      << quoted(name == "/tf_static" ? kLatchedQos : "") << "\n      message_count: " << t.messages << "\n";
  y << "  compression_format: \"\"\n  compression_mode: \"\"\n  relative_file_paths:\n    - " << file_name_
    << "\n  files:\n    - path: " << file_name_ << "\n      starting_time:\n        nanoseconds_since_epoch: "
    << first_ << "\n      duration:\n        nanoseconds: " << last_ - first_ << "\n      message_count: " << messages_
    << "\n";
  common::writeTextAtomically(path_ + "/metadata.yaml", y.str());
}

}  // namespace swslam::io

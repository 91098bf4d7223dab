#include <swslam/io/rawlog2bag.h>

#include <swslam/common/atomic_file.h>
#include <swslam/io/rawlog_reader.h>
#include <swslam/io/ros2_bag_writer.h>
#include <swslam/io/ros_conversion.h>

#include <mrpt/ros1bridge/time.h>
#include <rosbag/bag.h>

#include <filesystem>
#include <functional>
#include <sstream>

namespace swslam::io
{
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationOdometry;

namespace
{
ros::Time stampOf(const mrpt::obs::CObservation& obs, const std::string& what)
{
  if (obs.timestamp == mrpt::Clock::time_point{})
    throw std::runtime_error("rawlog2bag: " + what + " '" + obs.sensorLabel + "' has no timestamp");
  return mrpt::ros1bridge::toROS(obs.timestamp);
}


/** Where the conversion writes each message: a ROS 1 or a ROS 2 bag. */
struct Sink
{
  std::function<void(const std::string&, const ros::Time&, const tf2_msgs::TFMessage&)> tf;
  std::function<void(const std::string&, const ros::Time&, const nav_msgs::Odometry&)> odometry;
  std::function<void(const std::string&, const ros::Time&, const sensor_msgs::LaserScan&)> scan;
};

/** `time` turns a ros::Time into the bag's time. */
template <class Bag, class Time>
Sink sinkOf(Bag& bag, Time time)
{
  return {[&bag, time](const std::string& topic, const ros::Time& t, const tf2_msgs::TFMessage& m) {
            bag.write(topic, time(t), m);
          },
          [&bag, time](const std::string& topic, const ros::Time& t, const nav_msgs::Odometry& m) {
            bag.write(topic, time(t), m);
          },
          [&bag, time](const std::string& topic, const ros::Time& t, const sensor_msgs::LaserScan& m) {
            bag.write(topic, time(t), m);
          }};
}

/** The rawlog's scans of one sensor, its odometry and the scanner's mounting, into `sink`. */
Rawlog2BagStats convert(const Rawlog2BagOptions& opts, const Sink& sink)
{
  RawlogReader reader(opts.input);
  Rawlog2BagStats stats;
  stats.sensor_label = opts.sensor_label;
  std::optional<CObservationOdometry> from_actions;  // rawlog actions integrated
  RawlogItem item;
  while (reader.next(item))
  {
    if (item.odometry_increment)
    {
      if (!from_actions) from_actions.emplace();
      from_actions->odometry = from_actions->odometry + item.odometry_increment->poseChange->getMeanVal();
      from_actions->timestamp = mrpt::Clock::time_point{};  // stamped with the next scan
      stats.odometry++;
      continue;
    }
    if (auto scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(item.observation))
    {
      if (stats.sensor_label.empty()) stats.sensor_label = scan->sensorLabel;
      if (scan->sensorLabel != stats.sensor_label)
      {
        stats.other_labels[scan->sensorLabel]++;
        continue;
      }
      const ros::Time t = stampOf(*scan, "scan of");
      if (stats.scans == 0)  // the scanner's mounting, once (REP 105: latched /tf_static)
      {
        tf2_msgs::TFMessage tf;
        tf.transforms.push_back(transformToRos(scan->sensorPose, opts.base_frame, scan->sensorLabel, t));
        sink.tf("/tf_static", t, tf);
      }
      if (from_actions && from_actions->timestamp == mrpt::Clock::time_point{})
      {
        from_actions->timestamp = scan->timestamp;
        sink.odometry(opts.odom_topic, t, odometryToRos(*from_actions, opts.odom_frame, opts.base_frame));
      }
      sink.scan(opts.scan_topic, t, scanToRos(*scan, scan->sensorLabel));
      stats.scans++;
    }
    else if (auto odo = std::dynamic_pointer_cast<CObservationOdometry>(item.observation))
    {
      sink.odometry(opts.odom_topic, stampOf(*odo, "odometry"), odometryToRos(*odo, opts.odom_frame, opts.base_frame));
      stats.odometry++;
    }
    else
      stats.other_observations++;
  }
  if (stats.scans == 0)
    throw std::runtime_error("rawlog2bag: no scan" +
                             (opts.sensor_label.empty() ? "" : " of sensor '" + opts.sensor_label + "'") + " in '" +
                             opts.input + "'");
  return stats;
}

uint64_t nanoseconds(const ros::Time& t) { return t.toNSec(); }
const ros::Time& same(const ros::Time& t) { return t; }

/** A ROS 2 bag: a single .mcap file, or a rosbag2 folder written beside its final name and
 * renamed into place (an existing one, asked to be overwritten, replaced). */
Rawlog2BagStats writeRos2(const Rawlog2BagOptions& opts)
{
  namespace fs = std::filesystem;
  if (opts.compression != "none")
    throw std::invalid_argument("rawlog2bag: --compression " + opts.compression +
                                " is for ROS 1 bags (a ROS 2 bag's chunks are written uncompressed)");
  Rawlog2BagStats stats;
  const std::string name = fs::path(opts.output).filename().replace_extension().string();
  if (fs::path(opts.output).extension() == ".mcap")
  {
    common::writeAtomically(opts.output, [&](const std::string& tmp) {
      Ros2BagWriter bag(tmp, false, name);
      stats = convert(opts, sinkOf(bag, nanoseconds));
      bag.close();
    });
    return stats;
  }
  if (fs::exists(opts.output) && !fs::exists(fs::path(opts.output) / "metadata.yaml"))
    throw std::runtime_error("rawlog2bag: '" + opts.output + "' exists and is not a rosbag2 folder (no metadata.yaml)");
  const std::string tmp = opts.output + ".partial";
  fs::remove_all(tmp);
  try
  {
    Ros2BagWriter bag(tmp, true, name);
    stats = convert(opts, sinkOf(bag, nanoseconds));
    bag.close();
    fs::remove_all(opts.output);
    fs::rename(tmp, opts.output);
  }
  catch (...)
  {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    throw;
  }
  return stats;
}
}  // namespace

Rawlog2BagStats rawlog2bag(const Rawlog2BagOptions& opts)
{
  if (opts.format != "" && opts.format != "ros1" && opts.format != "ros2")
    throw std::invalid_argument("rawlog2bag: unknown format '" + opts.format + "' (ros1 or ros2)");
  if (opts.format == "ros2" || (opts.format.empty() && isRos2Output(opts.output))) return writeRos2(opts);
  const std::map<std::string, rosbag::compression::CompressionType> compressions{
      {"none", rosbag::compression::Uncompressed}, {"bz2", rosbag::compression::BZ2}, {"lz4", rosbag::compression::LZ4}};
  const auto compression = compressions.find(opts.compression);
  if (compression == compressions.end())
    throw std::invalid_argument("rawlog2bag: unknown compression '" + opts.compression + "' (none, bz2 or lz4)");
  Rawlog2BagStats stats;
  common::writeAtomically(opts.output, [&](const std::string& tmp) {
    rosbag::Bag bag(tmp, rosbag::bagmode::Write);
    bag.setCompression(compression->second);
    stats = convert(opts, sinkOf(bag, same));
    bag.close();
  });
  return stats;
}

std::string formatRawlog2BagStats(const Rawlog2BagStats& s, const Rawlog2BagOptions& opts)
{
  std::ostringstream o;
  o << "scans: " << s.scans << " of sensor '" << s.sensor_label << "' on " << opts.scan_topic << " (frame '"
    << s.sensor_label << "', its pose on '" << opts.base_frame << "' on /tf_static)\n";
  o << "odometry: " << s.odometry << " on " << opts.odom_topic << "\n";
  for (const auto& [label, n] : s.other_labels) o << "skipped " << n << " scans of sensor '" << label << "'\n";
  if (s.other_observations) o << "skipped " << s.other_observations << " other observations\n";
  return o.str();
}

}  // namespace swslam::io

#include <swslam/io/rawlog2bag.h>

#include <swslam/common/atomic_file.h>
#include <swslam/io/rawlog_reader.h>
#include <swslam/io/ros_conversion.h>

#include <mrpt/ros1bridge/time.h>
#include <rosbag/bag.h>

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
}  // namespace

Rawlog2BagStats rawlog2bag(const Rawlog2BagOptions& opts)
{
  const std::map<std::string, rosbag::compression::CompressionType> compressions{
      {"none", rosbag::compression::Uncompressed}, {"bz2", rosbag::compression::BZ2}, {"lz4", rosbag::compression::LZ4}};
  const auto compression = compressions.find(opts.compression);
  if (compression == compressions.end())
    throw std::invalid_argument("rawlog2bag: unknown compression '" + opts.compression + "' (none, bz2 or lz4)");
  RawlogReader reader(opts.input);
  Rawlog2BagStats stats;
  stats.sensor_label = opts.sensor_label;
  common::writeAtomically(opts.output, [&](const std::string& tmp) {
    rosbag::Bag bag(tmp, rosbag::bagmode::Write);
    bag.setCompression(compression->second);
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
          bag.write("/tf_static", t, tf);
        }
        if (from_actions && from_actions->timestamp == mrpt::Clock::time_point{})
        {
          from_actions->timestamp = scan->timestamp;
          bag.write(opts.odom_topic, t, odometryToRos(*from_actions, opts.odom_frame, opts.base_frame));
        }
        bag.write(opts.scan_topic, t, scanToRos(*scan, scan->sensorLabel));
        stats.scans++;
      }
      else if (auto odo = std::dynamic_pointer_cast<CObservationOdometry>(item.observation))
      {
        bag.write(opts.odom_topic, stampOf(*odo, "odometry"), odometryToRos(*odo, opts.odom_frame, opts.base_frame));
        stats.odometry++;
      }
      else
        stats.other_observations++;
    }
    if (stats.scans == 0)
      throw std::runtime_error("rawlog2bag: no scan" +
                               (opts.sensor_label.empty() ? "" : " of sensor '" + opts.sensor_label + "'") + " in '" +
                               opts.input + "'");
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

#include <swslam/io/ros2_bag_reader.h>

#include <swslam/io/ros2_messages.h>
#include <swslam/io/ros_conversion.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <algorithm>

namespace swslam::io
{
namespace
{
constexpr const char* kLaserScanType = Ros2BagReader::kScanType;
constexpr const char* kOdometryType = "nav_msgs/msg/Odometry";
constexpr const char* kTfType = "tf2_msgs/msg/TFMessage";
constexpr const char* kTfStaticTopic = "/tf_static";
/** Messages of one time read ahead (to give the odometry first), at most. */
constexpr size_t kMaxSameTime = 64;

/** The bag time as a ROS time (a message whose header stamp is zero takes it). */
ros::Time bagTime(uint64_t ns)
{
  if (ns / 1000000000u > UINT32_MAX) throw std::runtime_error("recorded at " + std::to_string(ns) + " ns, past 2106");
  ros::Time t;
  t.fromNSec(ns);
  return t;
}
}  // namespace

Ros2BagReader::Ros2BagReader(const std::string& path, const BagReaderOptions& opts)
    : BagReaderBase(path), storage_(openRos2Storage(path))
{
  topics_ = storage_->topics();
  chooseTopics(opts, kLaserScanType, kOdometryType);
  findSensorPose();
  std::vector<std::string> chosen;
  for (const BagTopic& t : topics())
    if (t.name == scan_topic_ || t.name == odom_topic_)
    {
      chosen.push_back(t.name);
      total_ += t.messages;
    }
  storage_->select(chosen);
}

bool Ros2BagReader::first(const std::string& topic, Ros2Message& out)
{
  storage_->select({topic});
  return storage_->next(out);
}

void Ros2BagReader::findSensorPose()
{
  mounting_.source = "identity";
  if (scan_topic_.empty()) return;
  std::string scan_frame, odom_child;
  Ros2Message m;
  try
  {
    if (!first(scan_topic_, m)) throw std::runtime_error("topic '" + scan_topic_ + "' has no message");
    scan_frame = laserScanFromCdr(m.data.data(), m.data.size()).header.frame_id;
    if (!odom_topic_.empty() && first(odom_topic_, m))
      odom_child = odometryFromCdr(m.data.data(), m.data.size()).child_frame_id;
  }
  catch (const std::exception& e)
  {
    mounting_.source = std::string("identity (the first message cannot be read: ") + e.what() + ")";
    return;
  }
  std::vector<geometry_msgs::TransformStamped> transforms;
  std::string tf_problem;
  const auto tf = std::find_if(topics().begin(), topics().end(), [](const BagTopic& t) {
    return t.name == kTfStaticTopic && t.type == kTfType;
  });
  if (tf != topics().end())
  {
    storage_->select({kTfStaticTopic});
    try
    {
      for (size_t i = 0; i < tf->messages && storage_->next(m); i++)  // the count known: no pass to the end
      {
        const auto msg = tfMessageFromCdr(m.data.data(), m.data.size());
        transforms.insert(transforms.end(), msg.transforms.begin(), msg.transforms.end());
      }
    }
    catch (const std::exception& e)  // the scans can still be read
    {
      tf_problem = e.what();
    }
  }
  mounting_ = mountingFromTf(scan_frame, odom_child, transforms, tf_problem, path_);
}

void Ros2BagReader::readSameTime()
{
  if ((scan_topic_.empty() && odom_topic_.empty()) || deferred_error_) return;
  std::string at;  // the message being read, for the error: " (topic at time)"
  try
  {
    uint64_t time = 0;
    while (pending_.size() < kMaxSameTime)
    {
      if (!lookahead_)
      {
        at.clear();
        auto m = std::make_unique<Ros2Message>();
        if (!storage_->next(*m)) break;
        lookahead_ = std::move(m);
      }
      const Ros2Message& m = *lookahead_;
      at = " (" + m.topic + " at " + std::to_string(m.time_ns) + " ns)";
      if (!pending_.empty() && m.time_ns != time) break;
      time = m.time_ns;
      // A message without a header stamp (some drivers leave it zero) is stamped with its bag time.
      if (m.topic == scan_topic_)
      {
        auto msg = laserScanFromCdr(m.data.data(), m.data.size());
        if (msg.header.stamp.isZero()) msg.header.stamp = bagTime(m.time_ns);
        pending_.push_back(
            std::make_shared<mrpt::obs::CObservation2DRangeScan>(scanFromRos(msg, scan_topic_, mounting_.pose)));
      }
      else
      {
        auto msg = odometryFromCdr(m.data.data(), m.data.size());
        if (msg.header.stamp.isZero()) msg.header.stamp = bagTime(m.time_ns);
        pending_.push_back(std::make_shared<mrpt::obs::CObservationOdometry>(odometryFromRos(msg, odom_topic_)));
      }
      lookahead_.reset();
    }
  }
  catch (const std::exception& e)  // the storage's, CDR's and the conversion's
  {
    failReading(at, e.what());
  }
  odometryFirst();
}

}  // namespace swslam::io

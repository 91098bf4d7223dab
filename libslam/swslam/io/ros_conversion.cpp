#include <swslam/io/ros_conversion.h>

#include <swslam/sensor/input_bounds.h>

#include <mrpt/ros1bridge/pose.h>
#include <mrpt/ros1bridge/time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>

namespace swslam::io
{
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationOdometry;
using mrpt::poses::CPose2D;
using mrpt::poses::CPose3D;

std::string laserScanAnglesProblem(double angle_min, double angle_max, double angle_increment, size_t rays)
{
  char buf[400];
  if (!std::isfinite(angle_increment) || angle_increment == 0 || !std::isfinite(angle_min) ||
      !std::isfinite(angle_max))
  {
    std::snprintf(buf, sizeof(buf), "a LaserScan with angle_min %g, angle_max %g and angle_increment %g rad",
                  angle_min, angle_max, angle_increment);
    return buf;
  }
  // Ray i is at angle_min + i angle_increment, the last at angle_max; some drivers state
  // angle_max one increment past the last ray (a full turn's 2 pi).
  const double last = angle_min + angle_increment * static_cast<double>(rays - 1);
  const double off = std::min(std::abs(last - angle_max), std::abs(last + angle_increment - angle_max));
  if (off <= kAngleTolerance * std::abs(angle_increment)) return "";
  std::snprintf(buf, sizeof(buf),
                "a LaserScan whose angles disagree: angle_min %.6g + %zu x angle_increment %.6g = %.6g rad, but "
                "angle_max is %.6g rad (%s): its rays' order is not the one its angles state",
                angle_min, rays - 1, angle_increment, last, angle_max,
                (angle_increment < 0) == (angle_max < angle_min)
                    ? "off by more than half an increment"
                    : (angle_increment < 0 ? "a negative increment from angle_min up to a larger angle_max"
                                           : "a positive increment from angle_min down to a smaller angle_max"));
  return buf;
}

CObservation2DRangeScan scanFromRos(const sensor_msgs::LaserScan& msg, const std::string& label,
                                    const CPose3D& sensor_pose)
{
  const size_t n = msg.ranges.size();
  if (n < 2) throw std::invalid_argument("a LaserScan of " + std::to_string(n) + " rays (at least 2 needed)");
  if (const std::string problem = sensor::rayCountProblem(n); !problem.empty()) throw std::invalid_argument(problem);
  if (const std::string problem = laserScanAnglesProblem(msg.angle_min, msg.angle_max, msg.angle_increment, n);
      !problem.empty())
    throw std::invalid_argument(problem);
  const double step = msg.angle_increment;
  // The fan: from angle_min to angle_max when that is its last ray, as the angles of a fan
  // written as float32 state it exactly (a rawlog's aperture comes back to the bit, and a
  // symmetric fan's middle to 0); else (angle_max one increment past the last ray) from the
  // increment.
  const double last = msg.angle_min + step * static_cast<double>(n - 1);
  const bool max_is_last = std::abs(last - msg.angle_max) <= std::abs(last + step - msg.angle_max);
  const double span = max_is_last ? double(msg.angle_max) - msg.angle_min : step * static_cast<double>(n - 1);
  CObservation2DRangeScan scan;
  scan.timestamp = mrpt::ros1bridge::fromROS(msg.header.stamp);
  scan.sensorLabel = label;
  scan.rightToLeft = true;
  scan.aperture = static_cast<float>(std::abs(span));
  scan.maxRange = msg.range_max;
  const double middle = msg.angle_min + span / 2;
  scan.sensorPose = sensor_pose + CPose3D(0, 0, 0, middle, 0, 0);
  scan.resizeScan(n);
  for (size_t i = 0; i < n; i++)
  {
    const float r = msg.ranges[step > 0 ? i : n - 1 - i];  // counter-clockwise either way
    const bool valid = std::isfinite(r) && r >= msg.range_min && r <= msg.range_max;
    scan.setScanRange(i, std::isfinite(r) ? r : msg.range_max);
    scan.setScanRangeValidity(i, valid);
  }
  return scan;
}

sensor_msgs::LaserScan scanToRos(const CObservation2DRangeScan& scan, const std::string& frame_id)
{
  const size_t n = scan.getScanSize();
  sensor_msgs::LaserScan msg;
  msg.header.stamp = mrpt::ros1bridge::toROS(scan.timestamp);
  msg.header.frame_id = frame_id;
  msg.angle_min = -0.5f * scan.aperture;
  msg.angle_max = 0.5f * scan.aperture;
  msg.angle_increment = n > 1 ? scan.aperture / (n - 1) : 0.0f;
  msg.range_min = 0;
  msg.range_max = scan.maxRange;
  msg.ranges.resize(n);
  for (size_t i = 0; i < n; i++)
  {
    const size_t k = scan.rightToLeft ? i : n - 1 - i;  // ROS rays go counter-clockwise
    msg.ranges[i] = scan.getScanRangeValidity(k) ? scan.getScanRange(k) : std::numeric_limits<float>::infinity();
  }
  return msg;
}

namespace
{
/** Throws std::invalid_argument unless `q` is a rotation: finite, of norm 1 within MRPT's
 * tolerance (its quaternion would throw a logic_error with a call stack). */
void requireRotation(const geometry_msgs::Quaternion& q)
{
  const double n2 = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  if (std::isfinite(n2) && std::abs(n2 - 1) < 1e-3) return;
  char buf[300];
  std::snprintf(buf, sizeof(buf), "a rotation quaternion (%g, %g, %g, %g) of norm %g, not 1", q.x, q.y, q.z, q.w,
                std::sqrt(n2));
  throw std::invalid_argument(buf);
}
}  // namespace

CObservationOdometry odometryFromRos(const nav_msgs::Odometry& msg, const std::string& label)
{
  requireRotation(msg.pose.pose.orientation);
  CObservationOdometry odo;
  odo.timestamp = mrpt::ros1bridge::fromROS(msg.header.stamp);
  odo.sensorLabel = label;
  odo.odometry = CPose2D(mrpt::ros1bridge::fromROS(msg.pose.pose));
  odo.hasVelocities = true;
  odo.velocityLocal = {msg.twist.twist.linear.x, msg.twist.twist.linear.y, msg.twist.twist.angular.z};
  return odo;
}

nav_msgs::Odometry odometryToRos(const CObservationOdometry& odo, const std::string& frame,
                                 const std::string& child_frame)
{
  nav_msgs::Odometry msg;
  msg.header.stamp = mrpt::ros1bridge::toROS(odo.timestamp);
  msg.header.frame_id = frame;
  msg.child_frame_id = child_frame;
  msg.pose.pose = mrpt::ros1bridge::toROS_Pose(odo.odometry);
  if (odo.hasVelocities)
  {
    msg.twist.twist.linear.x = odo.velocityLocal.vx;
    msg.twist.twist.linear.y = odo.velocityLocal.vy;
    msg.twist.twist.angular.z = odo.velocityLocal.omega;
  }
  return msg;
}

geometry_msgs::TransformStamped transformToRos(const CPose3D& pose, const std::string& parent,
                                               const std::string& child, const ros::Time& stamp)
{
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  const geometry_msgs::Pose p = mrpt::ros1bridge::toROS_Pose(pose);
  t.transform.translation.x = p.position.x;
  t.transform.translation.y = p.position.y;
  t.transform.translation.z = p.position.z;
  t.transform.rotation = p.orientation;
  return t;
}

CPose3D transformFromRos(const geometry_msgs::Transform& t)
{
  requireRotation(t.rotation);
  geometry_msgs::Pose p;
  p.position.x = t.translation.x;
  p.position.y = t.translation.y;
  p.position.z = t.translation.z;
  p.orientation = t.rotation;
  return mrpt::ros1bridge::fromROS(p);
}

bool poseInAncestor(const std::vector<geometry_msgs::TransformStamped>& transforms, const std::string& child,
                    const std::string& ancestor, CPose3D& pose)
{
  std::map<std::string, const geometry_msgs::TransformStamped*> parent_of;  // the last one stated wins
  for (const auto& t : transforms) parent_of[t.child_frame_id] = &t;
  CPose3D in_frame;  // pose of `child` in `frame`
  std::string frame = child;
  for (size_t hops = 0; hops <= transforms.size(); hops++)  // a cycle ends here too
  {
    if (frame == ancestor)
    {
      pose = in_frame;
      return true;
    }
    const auto it = parent_of.find(frame);
    if (it == parent_of.end()) return false;
    in_frame = transformFromRos(it->second->transform) + in_frame;
    frame = it->second->header.frame_id;
  }
  return false;
}

SensorMounting mountingFromTf(const std::string& scan_frame, const std::string& odom_child,
                              const std::vector<geometry_msgs::TransformStamped>& transforms,
                              const std::string& tf_problem, const std::string& path)
{
  const std::string base_frame = odom_child.empty() ? "base_link" : odom_child;
  SensorMounting m;
  if (scan_frame.empty() || scan_frame == base_frame)
  {
    m.source = "identity (the scans are in frame '" + base_frame + "')";
    return m;
  }
  if (!tf_problem.empty())
  {
    m.source = "identity (a /tf_static message cannot be read: " + tf_problem + ")";
    return m;
  }
  const std::string link = "/tf_static '" + base_frame + "' -> '" + scan_frame + "'";
  bool linked = false;
  try
  {
    linked = poseInAncestor(transforms, scan_frame, base_frame, m.pose);
  }
  catch (const std::invalid_argument& e)  // a transform that is no pose
  {
    throw std::runtime_error("bag '" + path + "': " + link + ": " + e.what());
  }
  if (!linked)
  {
    m.source = "identity (no /tf_static transform from '" + base_frame + "' to '" + scan_frame + "')";
    return m;
  }
  m.source = link;
  if (const std::string problem = sensor::mountingProblem(m.pose); !problem.empty())
    throw std::runtime_error("bag '" + path + "': " + m.source + ": " + problem);
  return m;
}

namespace
{
/** Walks serialized ROS message bytes, checking each length against what is left. */
class LayoutCursor
{
 public:
  explicit LayoutCursor(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
  bool skip(uint64_t n)
  {
    if (n > bytes_.size() - at_) return false;
    at_ += n;
    return true;
  }
  bool u32(uint32_t& v)
  {
    if (4 > bytes_.size() - at_) return false;
    std::memcpy(&v, bytes_.data() + at_, 4);  // ROS serializes little-endian, as x86 and ARM run
    at_ += 4;
    return true;
  }
  /** A length-prefixed array of `element` bytes per item (strings: 1); its length in `n`. */
  bool array(uint64_t element, uint32_t& n)
  {
    return u32(n) && skip(element * n);
  }
  bool array(uint64_t element)
  {
    uint32_t n = 0;
    return array(element, n);
  }
  bool header() { return skip(4 + 8) && array(1); }  // seq, stamp, frame_id
  bool atEnd() const { return at_ == bytes_.size(); }
  size_t offset() const { return at_; }

 private:
  const std::vector<uint8_t>& bytes_;
  size_t at_ = 0;
};

std::string ended(const LayoutCursor& c, size_t size)
{
  return "a length at byte " + std::to_string(c.offset()) + " runs past the message's " + std::to_string(size) +
         " bytes";
}
}  // namespace

std::string laserScanLayoutProblem(const std::vector<uint8_t>& bytes)
{
  LayoutCursor c(bytes);
  uint32_t rays = 0, intensities = 0;
  if (!c.header() || !c.skip(7 * 4) || !c.array(4, rays) || !c.array(4, intensities)) return ended(c, bytes.size());
  if (!c.atEnd()) return std::to_string(bytes.size() - c.offset()) + " bytes past the scan's end";
  return sensor::rayCountProblem(std::max(rays, intensities));
}

std::string tfMessageLayoutProblem(const std::vector<uint8_t>& bytes)
{
  LayoutCursor c(bytes);
  uint32_t n = 0;
  if (!c.u32(n)) return ended(c, bytes.size());
  for (uint32_t i = 0; i < n; i++)  // each transform takes at least 76 bytes: the bytes bound the loop
    if (!c.header() || !c.array(1) || !c.skip(7 * 8)) return ended(c, bytes.size());
  if (!c.atEnd()) return std::to_string(bytes.size() - c.offset()) + " bytes past the transforms' end";
  return "";
}

}  // namespace swslam::io

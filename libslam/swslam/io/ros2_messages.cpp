#include <swslam/io/ros2_messages.h>

#include <swslam/io/cdr_reader.h>
#include <swslam/io/cdr_writer.h>
#include <swslam/sensor/input_bounds.h>

namespace swslam::io
{
namespace
{
/** builtin_interfaces/msg/Time as a ros::Time (unsigned seconds). */
ros::Time stamp(CdrReader& c)
{
  const int32_t sec = c.i32();
  const uint32_t nanosec = c.u32();
  if (sec < 0) c.fail("a stamp of " + std::to_string(sec) + " s, before 1970");
  if (nanosec >= 1000000000u) c.fail("a stamp of " + std::to_string(nanosec) + " ns past its second");
  return ros::Time(static_cast<uint32_t>(sec), nanosec);
}

/** std_msgs/msg/Header: stamp, frame_id. */
std_msgs::Header header(CdrReader& c)
{
  std_msgs::Header h;
  h.stamp = stamp(c);
  h.frame_id = c.string();
  return h;
}

void vector3(CdrReader& c, double& x, double& y, double& z)
{
  x = c.f64();
  y = c.f64();
  z = c.f64();
}

geometry_msgs::Quaternion quaternion(CdrReader& c)
{
  geometry_msgs::Quaternion q;
  q.x = c.f64();
  q.y = c.f64();
  q.z = c.f64();
  q.w = c.f64();
  return q;
}

void covariance(CdrReader& c, boost::array<double, 36>& cov)
{
  for (double& v : cov) v = c.f64();
}

/** A sequence of floats holding scan rays: the count checked against the rays' bound first. */
std::vector<float> rays(CdrReader& c)
{
  const uint32_t n = c.u32();
  if (const std::string problem = sensor::rayCountProblem(n); !problem.empty()) c.fail(problem);
  return c.f32Array(n);
}
}  // namespace

sensor_msgs::LaserScan laserScanFromCdr(const uint8_t* data, size_t size)
{
  CdrReader c(data, size);
  sensor_msgs::LaserScan m;
  m.header = header(c);
  m.angle_min = c.f32();
  m.angle_max = c.f32();
  m.angle_increment = c.f32();
  m.time_increment = c.f32();
  m.scan_time = c.f32();
  m.range_min = c.f32();
  m.range_max = c.f32();
  m.ranges = rays(c);
  m.intensities = rays(c);
  c.expectEnd();
  return m;
}

nav_msgs::Odometry odometryFromCdr(const uint8_t* data, size_t size)
{
  CdrReader c(data, size);
  nav_msgs::Odometry m;
  m.header = header(c);
  m.child_frame_id = c.string();
  auto& pose = m.pose.pose;
  vector3(c, pose.position.x, pose.position.y, pose.position.z);
  pose.orientation = quaternion(c);
  covariance(c, m.pose.covariance);
  auto& twist = m.twist.twist;
  vector3(c, twist.linear.x, twist.linear.y, twist.linear.z);
  vector3(c, twist.angular.x, twist.angular.y, twist.angular.z);
  covariance(c, m.twist.covariance);
  c.expectEnd();
  return m;
}

tf2_msgs::TFMessage tfMessageFromCdr(const uint8_t* data, size_t size)
{
  CdrReader c(data, size);
  tf2_msgs::TFMessage m;
  // A transform takes at least 72 bytes (stamp 8, two string lengths 8, seven float64 56):
  // the bytes left bound the count before the loop.
  const uint32_t n = c.sequenceLength(72);
  m.transforms.resize(n);
  for (auto& t : m.transforms)
  {
    t.header = header(c);
    t.child_frame_id = c.string();
    vector3(c, t.transform.translation.x, t.transform.translation.y, t.transform.translation.z);
    t.transform.rotation = quaternion(c);
  }
  c.expectEnd();
  return m;
}

std::vector<uint8_t> laserScanCdr(const sensor_msgs::LaserScan& m, bool big_endian)
{
  CdrWriter c(big_endian);
  c.header(m.header);
  for (float v : {m.angle_min, m.angle_max, m.angle_increment, m.time_increment, m.scan_time, m.range_min, m.range_max})
    c.put<float>(v);
  return c.floats(m.ranges).floats(m.intensities).bytes();
}

std::vector<uint8_t> odometryCdr(const nav_msgs::Odometry& m, bool big_endian)
{
  CdrWriter c(big_endian);
  c.header(m.header).str(m.child_frame_id);
  const auto& p = m.pose.pose;
  for (double v : {p.position.x, p.position.y, p.position.z, p.orientation.x, p.orientation.y, p.orientation.z,
                   p.orientation.w})
    c.put<double>(v);
  for (double v : m.pose.covariance) c.put<double>(v);
  const auto& t = m.twist.twist;
  for (double v : {t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z}) c.put<double>(v);
  for (double v : m.twist.covariance) c.put<double>(v);
  return c.bytes();
}

std::vector<uint8_t> tfMessageCdr(const tf2_msgs::TFMessage& m, bool big_endian)
{
  CdrWriter c(big_endian);
  c.put<uint32_t>(static_cast<uint32_t>(m.transforms.size()));
  for (const auto& t : m.transforms)
  {
    c.header(t.header).str(t.child_frame_id);
    const auto& tr = t.transform;
    for (double v : {tr.translation.x, tr.translation.y, tr.translation.z, tr.rotation.x, tr.rotation.y,
                     tr.rotation.z, tr.rotation.w})
      c.put<double>(v);
  }
  return c.bytes();
}

}  // namespace swslam::io

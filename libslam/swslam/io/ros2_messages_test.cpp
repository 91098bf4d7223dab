// The three ROS 2 messages from CDR: round trips in both byte orders against hand-laid
// buffers, every truncation named, the ray bound before any allocation.
#include <swslam/io/cdr_reader.h>
#include <swslam/io/ros2_messages.h>
#include <swslam/io/cdr_writer.h>
#include <swslam/sensor/input_bounds.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam::io;
using swslam::test::errorOf;

namespace
{
sensor_msgs::LaserScan scan()
{
  sensor_msgs::LaserScan m;
  m.header.stamp = ros::Time(1700000000, 123456789);
  m.header.frame_id = "laser";
  m.angle_min = -1.5f;
  m.angle_max = 1.5f;
  m.angle_increment = 1.0f;
  m.time_increment = 0.001f;
  m.scan_time = 0.1f;
  m.range_min = 0.1f;
  m.range_max = 30.0f;
  m.ranges = {1.0f, 2.0f, NAN, INFINITY};
  m.intensities = {5.0f};
  return m;
}

nav_msgs::Odometry odometry()
{
  nav_msgs::Odometry m;
  m.header.stamp = ros::Time(1700000000, 5);
  m.header.frame_id = "odom";
  m.child_frame_id = "base_footprint";
  m.pose.pose.position.x = 1.5;
  m.pose.pose.position.y = -2.25;
  m.pose.pose.orientation.z = std::sin(0.25);
  m.pose.pose.orientation.w = std::cos(0.25);
  m.pose.covariance[35] = 0.01;
  m.twist.twist.linear.x = 0.5;
  m.twist.twist.angular.z = -0.125;
  return m;
}

tf2_msgs::TFMessage transforms()
{
  tf2_msgs::TFMessage m;
  for (int i = 0; i < 2; i++)
  {
    geometry_msgs::TransformStamped t;
    t.header.stamp = ros::Time(1700000000 + i, 0);
    t.header.frame_id = i ? "base_link" : "base_footprint";
    t.child_frame_id = i ? "laser" : "base_link";
    t.transform.translation.x = 0.1 * (i + 1);
    t.transform.translation.z = 0.3;
    t.transform.rotation.w = 1;
    m.transforms.push_back(t);
  }
  return m;
}
}  // namespace

TEST(Ros2Messages, ALaserScanRoundTripsInBothByteOrders)
{
  for (bool big : {false, true})
  {
    const auto bytes = laserScanCdr(scan(), big);
    const sensor_msgs::LaserScan m = laserScanFromCdr(bytes.data(), bytes.size());
    EXPECT_EQ(m.header.stamp, scan().header.stamp);
    EXPECT_EQ(m.header.frame_id, "laser");
    EXPECT_EQ(m.angle_min, -1.5f);
    EXPECT_EQ(m.angle_max, 1.5f);
    EXPECT_EQ(m.angle_increment, 1.0f);
    EXPECT_EQ(m.time_increment, 0.001f);
    EXPECT_EQ(m.scan_time, 0.1f);
    EXPECT_EQ(m.range_min, 0.1f);
    EXPECT_EQ(m.range_max, 30.0f);
    ASSERT_EQ(m.ranges.size(), 4u);
    EXPECT_EQ(m.ranges[1], 2.0f);
    EXPECT_TRUE(std::isnan(m.ranges[2]));
    EXPECT_EQ(m.ranges[3], INFINITY);
    EXPECT_EQ(m.intensities, std::vector<float>{5.0f});
  }
}

TEST(Ros2Messages, OdometryAndTransformsRoundTripInBothByteOrders)
{
  for (bool big : {false, true})
  {
    const auto ob = odometryCdr(odometry(), big);
    const nav_msgs::Odometry o = odometryFromCdr(ob.data(), ob.size());
    EXPECT_EQ(o, odometry());
    const auto tb = tfMessageCdr(transforms(), big);
    const tf2_msgs::TFMessage t = tfMessageFromCdr(tb.data(), tb.size());
    EXPECT_EQ(t, transforms());
  }
}

TEST(Ros2Messages, EveryTruncationIsANamedError)
{
  for (bool big : {false, true})
  {
    const std::vector<std::vector<uint8_t>> all{laserScanCdr(scan(), big), odometryCdr(odometry(), big),
                                                tfMessageCdr(transforms(), big)};
    for (size_t k = 0; k < all.size(); k++)
      for (size_t n = 0; n + 4 <= all[k].size(); n++)  // shorter by 4 or more: padding cannot explain it
      {
        const uint8_t* p = all[k].data();
        const std::string e = errorOf([&] {
          if (k == 0) laserScanFromCdr(p, n);
          if (k == 1) odometryFromCdr(p, n);
          if (k == 2) tfMessageFromCdr(p, n);
        });
        EXPECT_EQ(e.rfind("CDR byte ", 0), 0u) << "message " << k << " cut to " << n << " bytes: '" << e << "'";
      }
  }
}

TEST(Ros2Messages, AScanOfMoreRaysThanTheBoundIsRefusedBeforeAnyAllocation)
{
  sensor_msgs::LaserScan m = scan();
  m.ranges.clear();
  auto bytes = laserScanCdr(m, false);
  // The ranges' count (4 bytes before the intensities' count and its one float) made 2^20 + 1.
  const size_t count_at = bytes.size() - 4 - 4 - 4;
  const uint32_t n = swslam::sensor::kMaxScanRays + 1;
  std::memcpy(bytes.data() + count_at, &n, 4);
  EXPECT_NE(errorOf([&] { laserScanFromCdr(bytes.data(), bytes.size()); }).find("a scan of 1048577 rays"),
            std::string::npos);
}

TEST(Ros2Messages, AStampBefore1970OrPastItsSecondIsNamed)
{
  CdrWriter c(false);
  c.put<int32_t>(-5).put<uint32_t>(0).str("laser");
  auto b = c.bytes();
  EXPECT_NE(errorOf([&] { laserScanFromCdr(b.data(), b.size()); }).find("a stamp of -5 s, before 1970"),
            std::string::npos);
  CdrWriter d(false);
  d.put<int32_t>(5).put<uint32_t>(1000000000u).str("laser");
  b = d.bytes();
  EXPECT_NE(errorOf([&] { odometryFromCdr(b.data(), b.size()); }).find("ns past its second"), std::string::npos);
}

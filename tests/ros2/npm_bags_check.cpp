// Reads the ROS 2 bags that tests/ros2/make-bags.mjs wrote with the npm writers (@mcap/core,
// @foxglove/cdr, sqlite3), in every variant: the synthetic drive gives the scans, odometry and
// mounting make-bags.mjs states; lake-short gives every observation the ROS 1 bag of the same
// messages gives, to the byte (serialized by MRPT). A ctest test of the fixture ros2_bags.
// Usage: swslam_ros2_npm_bags_check BAGS_DIR [gtest options]
#include <swslam/io/bag_reader.h>
#include <swslam/io/ros2_bag_reader.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/datetime.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam::io;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationOdometry;

namespace
{
std::string g_bags;
const std::vector<std::string> kVariants{"zstd.mcap", "be.mcap", "unchunked.mcap", "lz4",
                                        "db3",       "db3-zstd", "db3-file-zstd"};

std::vector<mrpt::obs::CObservation::Ptr> observations(BagReaderBase& r)
{
  std::vector<mrpt::obs::CObservation::Ptr> out;
  mrpt::obs::CObservation::Ptr o;
  while (r.next(o)) out.push_back(o);
  return out;
}

std::vector<uint8_t> bytesOf(const mrpt::obs::CObservation::Ptr& o)
{
  std::vector<uint8_t> b;
  mrpt::serialization::ObjectToOctetVector(o.get(), b);
  return b;
}

double seconds(const mrpt::Clock::time_point& t) { return mrpt::Clock::toDouble(t); }
}  // namespace

TEST(Ros2NpmBags, TheSyntheticDriveReadsAsMakeBagsWroteIt)
{
  for (const std::string& v : kVariants)
  {
    SCOPED_TRACE(v);
    Ros2BagReader r(g_bags + "/synthetic/" + v, {});
    EXPECT_EQ(formatTopics(r.topics()),
              "/odom (nav_msgs/msg/Odometry, 5 messages), /scan (sensor_msgs/msg/LaserScan, 5 messages), "
              "/tf_static (tf2_msgs/msg/TFMessage, 1 message)");
    EXPECT_EQ(r.sensorPoseSource(), "/tf_static 'base_link' -> 'laser'");
    EXPECT_NEAR(r.sensorPose().x(), 0.2, 1e-12);
    EXPECT_NEAR(r.sensorPose().z(), 0.3, 1e-12);
    EXPECT_NEAR(r.sensorPose().yaw(), 0.0, 1e-12);
    const auto all = observations(r);
    ASSERT_EQ(all.size(), 10u);
    std::vector<CObservation2DRangeScan::Ptr> scans;
    std::vector<CObservationOdometry::Ptr> odometry;
    for (size_t i = 0; i < all.size(); i++)
    {
      if (auto s = std::dynamic_pointer_cast<CObservation2DRangeScan>(all[i])) scans.push_back(s);
      if (auto o = std::dynamic_pointer_cast<CObservationOdometry>(all[i])) odometry.push_back(o);
      EXPECT_EQ(i % 2 == 0, std::dynamic_pointer_cast<CObservationOdometry>(all[i]) != nullptr) << "odometry first";
    }
    ASSERT_EQ(scans.size(), 5u);
    ASSERT_EQ(odometry.size(), 5u);
    EXPECT_NEAR(seconds(scans.front()->timestamp), 1000.0, 1e-6);
    EXPECT_NEAR(seconds(scans.back()->timestamp), 1000.4, 1e-6);
    for (const auto& s : {scans.front(), scans.back()})
    {
      ASSERT_EQ(s->getScanSize(), 181u);
      EXPECT_EQ(s->sensorLabel, "/scan");
      EXPECT_NEAR(s->aperture, M_PI, 1e-6);
      EXPECT_FALSE(s->getScanRangeValidity(0));  // NaN: no return
      EXPECT_TRUE(s->getScanRangeValidity(180));
      EXPECT_FLOAT_EQ(s->getScanRange(180), 3.0f);  // straight left, the wall 3 m away
      EXPECT_NEAR(s->sensorPose.x(), 0.2, 1e-12);
    }
    EXPECT_FLOAT_EQ(scans.front()->getScanRange(90), 6.8f);  // ahead: from x = -1.8 to the wall at 5
    EXPECT_FLOAT_EQ(scans.back()->getScanRange(90), 6.0f);
    EXPECT_NEAR(odometry.front()->odometry.x(), -2.0, 1e-12);
    EXPECT_NEAR(odometry.back()->odometry.x(), -1.2, 1e-12);
    EXPECT_NEAR(odometry.back()->velocityLocal.vx, 2.0, 1e-12);
  }
}

TEST(Ros2NpmBags, LakeShortGivesTheObservationsOfTheROS1BagToTheByte)
{
  BagReader ros1(g_bags + "/lake-short.bag", {});
  const auto expected = observations(ros1);
  ASSERT_EQ(expected.size(), 2u * 2461);
  for (const std::string& v : kVariants)
  {
    Ros2BagReader r(g_bags + "/lake-short/" + v, {});
    EXPECT_EQ(r.sensorPose(), ros1.sensorPose()) << v;
    const auto got = observations(r);
    ASSERT_EQ(got.size(), expected.size()) << v;
    size_t differ = 0;
    for (size_t i = 0; i < got.size(); i++) differ += bytesOf(got[i]) != bytesOf(expected[i]);
    EXPECT_EQ(differ, 0u) << v;
  }
}

int main(int argc, char** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: %s BAGS_DIR (tests/ros2/make-bags.sh writes it)\n", argv[0]);
    return 2;
  }
  g_bags = argv[1];
  return RUN_ALL_TESTS();
}

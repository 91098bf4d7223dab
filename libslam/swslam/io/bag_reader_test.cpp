// Reading ROS 1 bags: scans and odometry in time order, topic choice, the sensor pose from
// /tf_static, and damaged bags. The bags are written with librosbag's own writer.
#include <swslam/io/bag_reader.h>
#include <swslam/io/ros1_bag_layout.h>
#include <swslam/io/ros_conversion.h>
#include <swslam/io/scan_source.h>
#include <swslam/sensor/input_bounds.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <rosbag/bag.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

using namespace swslam;
using namespace swslam::io;
using swslam::test::errorOf;
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationOdometry;

namespace
{
constexpr size_t kRays = 181;
constexpr double kT0 = 1000.0;

/** Scan k: 181 rays over 180 deg, ray 0 at 1 + 0.1 k m (unique: the corruption test finds it);
 * rays 5-8 are NaN, +inf, below range_min and above range_max. */
sensor_msgs::LaserScan scanMessage(int k, const std::string& frame = "laser")
{
  sensor_msgs::LaserScan m;
  m.header.stamp = ros::Time(kT0 + 0.1 * k);
  m.header.frame_id = frame;
  m.angle_min = -M_PI / 2;
  m.angle_increment = M_PI / (kRays - 1);
  m.angle_max = m.angle_min + m.angle_increment * (kRays - 1);
  m.range_min = 0.05f;
  m.range_max = 30.0f;
  for (size_t i = 0; i < kRays; i++) m.ranges.push_back(1.0f + 0.1f * k + 0.01f * i);
  m.ranges[5] = std::nanf("");
  m.ranges[6] = INFINITY;
  m.ranges[7] = 0.01f;
  m.ranges[8] = 31.0f;
  return m;
}

nav_msgs::Odometry odomMessage(int k, const std::string& child = "base_link")
{
  nav_msgs::Odometry m;
  m.header.stamp = ros::Time(kT0 + 0.1 * k - 0.05);
  m.header.frame_id = "odom";
  m.child_frame_id = child;
  m.pose.pose.position.x = 0.2 * k;
  m.pose.pose.orientation.w = 1;
  return m;
}

struct BagSpec
{
  int scans = 10;
  std::vector<std::string> scan_topics{"/scan"};
  std::vector<std::string> odom_topics{"/odom"};
  std::vector<geometry_msgs::TransformStamped> tf_static;
  rosbag::CompressionType compression = rosbag::compression::Uncompressed;
};

std::string writeBag(const std::string& name, const BagSpec& spec)
{
  const std::string path = (std::filesystem::temp_directory_path() / ("swslam_bag_" + name + ".bag")).string();
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  bag.setChunkThreshold(4096);  // many chunks: damage hits one in the middle
  bag.setCompression(spec.compression);
  if (!spec.tf_static.empty())
  {
    tf2_msgs::TFMessage tf;
    tf.transforms = spec.tf_static;
    bag.write("/tf_static", ros::Time(kT0 - 1), tf);
  }
  for (int k = 0; k < spec.scans; k++)
  {
    for (const auto& topic : spec.odom_topics) bag.write(topic, odomMessage(k).header.stamp, odomMessage(k));
    for (const auto& topic : spec.scan_topics) bag.write(topic, scanMessage(k).header.stamp, scanMessage(k));
  }
  bag.close();
  return path;
}

struct ReadResult
{
  std::vector<CObservation2DRangeScan::Ptr> scans;
  std::vector<CObservationOdometry::Ptr> odometry;
  std::vector<double> times;
};

ReadResult readAll(BagReader& r)
{
  ReadResult out;
  mrpt::obs::CObservation::Ptr obs;
  while (r.next(obs))
  {
    out.times.push_back(mrpt::Clock::toDouble(obs->timestamp));
    if (auto s = std::dynamic_pointer_cast<CObservation2DRangeScan>(obs)) out.scans.push_back(s);
    if (auto o = std::dynamic_pointer_cast<CObservationOdometry>(obs)) out.odometry.push_back(o);
  }
  return out;
}

}  // namespace

TEST(BagReader, ScansAndOdometryInTimeOrder)
{
  const std::string path = writeBag("plain", {});
  BagReader r(path, {});
  EXPECT_EQ(r.scanTopic(), "/scan");
  EXPECT_EQ(r.odomTopic(), "/odom");
  const ReadResult got = readAll(r);
  ASSERT_EQ(got.scans.size(), 10u);
  ASSERT_EQ(got.odometry.size(), 10u);
  EXPECT_TRUE(std::is_sorted(got.times.begin(), got.times.end()));
  EXPECT_DOUBLE_EQ(r.fractionRead(), 1.0);
  const CObservation2DRangeScan& s = *got.scans[3];
  EXPECT_EQ(s.sensorLabel, "/scan");
  EXPECT_NEAR(mrpt::Clock::toDouble(s.timestamp), kT0 + 0.3, 1e-6);
  ASSERT_EQ(s.getScanSize(), kRays);
  EXPECT_NEAR(s.aperture, M_PI, 1e-6);
  EXPECT_FLOAT_EQ(s.maxRange, 30.0f);
  EXPECT_NEAR(s.sensorPose.norm(), 0, 1e-9);  // identity (no /tf_static)
  EXPECT_NEAR(s.sensorPose.yaw(), 0, 1e-6);   // a symmetric fan
  const auto msg = scanMessage(3);
  for (size_t i = 0; i < kRays; i++)
  {
    const bool special = i >= 5 && i <= 8;
    EXPECT_EQ(s.getScanRangeValidity(i), !special) << i;
    if (!special) EXPECT_EQ(s.getScanRange(i), msg.ranges[i]) << i;  // every ray at its own index
    EXPECT_TRUE(std::isfinite(s.getScanRange(i))) << i;
  }
  EXPECT_NEAR(got.odometry[4]->odometry.x(), 0.8, 1e-12);
  EXPECT_EQ(got.odometry[4]->sensorLabel, "/odom");
  EXPECT_NE(r.sensorPoseSource().find("identity (no /tf_static transform from 'base_link' to 'laser')"),
            std::string::npos)
      << r.sensorPoseSource();
}

TEST(BagReader, RaysKeepTheirAnglesInAnAsymmetricOrReversedFan)
{
  sensor_msgs::LaserScan m = scanMessage(0);
  m.angle_min = -0.5f;
  m.angle_increment = 0.01f;
  m.ranges.clear();
  for (int i = 0; i < 101; i++) m.ranges.push_back(2.0f + 0.01f * i);
  const mrpt::poses::CPose3D mount(0.3, 0.1, 0, 0.2, 0, 0);
  for (const bool reversed : {false, true})
  {
    sensor_msgs::LaserScan msg = m;
    msg.angle_max = -0.5f + 0.01f * 100;
    if (reversed)
    {
      msg.angle_min = -0.5f + 0.01f * 100;  // the same rays, listed clockwise (right to left)
      msg.angle_max = -0.5f;
      msg.angle_increment = -0.01f;
      std::reverse(msg.ranges.begin(), msg.ranges.end());
    }
    const CObservation2DRangeScan s = scanFromRos(msg, "/scan", mount);
    ASSERT_EQ(s.getScanSize(), 101u);
    for (size_t i = 0; i < 101; i++)
    {
      // MRPT's ray i points at -aperture/2 + i * aperture/(N-1) from the sensor's x axis.
      const double angle = s.sensorPose.yaw() - s.aperture / 2 + i * s.aperture / 100;
      EXPECT_NEAR(angle, 0.2 - 0.5 + 0.01 * i, 1e-6) << i << (reversed ? " reversed" : "");
      EXPECT_EQ(s.getScanRange(i), m.ranges[i]) << i;
    }
    EXPECT_NEAR(s.sensorPose.x(), 0.3, 1e-9);
  }
  m.angle_increment = 0;
  EXPECT_THROW(scanFromRos(m, "/scan", mount), std::invalid_argument);
}

namespace
{
/** The bag of BagSpec's defaults with `last` appended on /scan after its messages, read to
 * the end: the messages read, and the error that stopped the reading. */
std::pair<size_t, std::string> readWithLastScan(const std::string& name, sensor_msgs::LaserScan last)
{
  const std::string path = writeBag(name, {});
  {
    rosbag::Bag bag(path, rosbag::bagmode::Append);
    last.header.stamp = ros::Time(kT0 + 5);
    bag.write("/scan", last.header.stamp, last);
  }
  BagReader r(path, {});
  mrpt::obs::CObservation::Ptr obs;
  size_t read = 0;
  const std::string e = errorOf([&] {
    while (r.next(obs)) read++;
  });
  return {read, e};
}
}  // namespace

TEST(BagReader, AScanWhoseAnglesDisagreeIsANamedError)
{
  // A negative increment with angle_min < angle_max read as a scan turned by half a turn
  // (the trajectory by 90 degrees), with no word.
  sensor_msgs::LaserScan m = scanMessage(0);  // 181 rays, -90 to +90 degrees
  const mrpt::poses::CPose3D mount;
  const auto error = [&](const sensor_msgs::LaserScan& msg) {
    return errorOf([&] { scanFromRos(msg, "/scan", mount); });
  };
  EXPECT_EQ(error(m), "");
  sensor_msgs::LaserScan inconsistent = m;
  inconsistent.angle_increment = -m.angle_increment;
  EXPECT_NE(error(inconsistent).find("a LaserScan whose angles disagree: angle_min -1.5708 + 180 x angle_increment "
                                     "-0.0174533 = -4.71239 rad, but angle_max is 1.5708 rad (a negative increment "
                                     "from angle_min up to a larger angle_max)"),
            std::string::npos)
      << error(inconsistent);
  sensor_msgs::LaserScan upside = m;  // a positive increment down to a smaller angle_max
  std::swap(upside.angle_min, upside.angle_max);
  EXPECT_NE(error(upside).find("a positive increment from angle_min down to a smaller angle_max"), std::string::npos)
      << error(upside);
  // Within half an increment, or stating the end of the last ray's increment (a full turn's
  // 2 pi): agrees. Off by more: the increment does not fit the rays.
  sensor_msgs::LaserScan close = m;
  close.angle_max += 0.4f * m.angle_increment;
  EXPECT_EQ(error(close), "");
  sensor_msgs::LaserScan past = m;
  past.angle_max += m.angle_increment;
  EXPECT_EQ(error(past), "");
  sensor_msgs::LaserScan off = m;
  off.angle_max += 2.5f * m.angle_increment;
  EXPECT_NE(error(off).find("off by more than half an increment"), std::string::npos) << error(off);
  sensor_msgs::LaserScan nan = m;
  nan.angle_max = NAN;
  EXPECT_NE(error(nan).find("angle_max nan"), std::string::npos) << error(nan);

  // In a bag: the reading stops at it, naming the message.
  const auto [read, e] = readWithLastScan("angles", inconsistent);
  EXPECT_EQ(read, 20u);
  EXPECT_NE(e.find("message #20 of 21 cannot be read (/scan at"), std::string::npos) << e;
  EXPECT_NE(e.find("angles disagree"), std::string::npos) << e;
}

TEST(BagReader, AScanOfMoreRaysThanARawlogAllowsIsRefused)
{
  // One LaserScan of 10 million rays was read (639 MB); rawlogs refuse more than 2^20.
  sensor_msgs::LaserScan big = scanMessage(0);
  big.ranges.assign(sensor::kMaxScanRays + 1, 2.0f);
  big.angle_increment = static_cast<float>(2 * M_PI / big.ranges.size());
  big.angle_min = -M_PI;
  big.angle_max = big.angle_min + big.angle_increment * (big.ranges.size() - 1);
  const std::string expected = "a scan of 1048577 rays (more than 1048576: a corrupt count)";
  EXPECT_EQ(errorOf([&] { scanFromRos(big, "/scan", {}); }), expected);
  const auto [read, e] = readWithLastScan("many_rays", big);
  EXPECT_EQ(read, 20u);
  EXPECT_NE(e.find("message #20 of 21 cannot be read (/scan at"), std::string::npos) << e;
  EXPECT_NE(e.find(expected), std::string::npos) << e;
}

TEST(BagReader, AStaticTransformMountingTheScannerBeyondTheBoundIsANamedError)
{
  // /tf_static saying x = 1e30 corrupted the search's grid in threaded swslam.
  for (const double x : {1e30, 1e4, 60.0})
  {
    BagSpec spec;
    spec.tf_static = {transformToRos(mrpt::poses::CPose3D(x, 0, 0.1, 0, 0, 0), "base_link", "laser", ros::Time(kT0))};
    const std::string path = writeBag("far_mount", spec);
    const std::string e = errorOf([&] { BagReader r(path, {}); });
    EXPECT_NE(e.find("bag '" + path + "': /tf_static 'base_link' -> 'laser': sensor mounted at ("), std::string::npos)
        << e;
    EXPECT_NE(e.find("beyond the 50 m"), std::string::npos) << e;
  }
}

TEST(BagReader, TopicsAreChosenOrNamed)
{
  BagSpec two;
  two.scan_topics = {"/front/scan", "/rear/scan"};
  two.odom_topics = {"/odom", "/wheel_odom"};
  const std::string path = writeBag("two", two);
  const std::string several = errorOf([&] { BagReader r(path, {}); });
  EXPECT_NE(several.find("2 sensor_msgs/LaserScan topics (/front/scan, /rear/scan): choose one with --scan-topic"),
            std::string::npos)
      << several;
  const std::string odometries = errorOf([&] { BagReader r(path, {"/rear/scan", "", true}); });
  EXPECT_NE(odometries.find("(/odom, /wheel_odom): choose one with --odom-topic"), std::string::npos) << odometries;
  {
    BagReader r(path, {"/rear/scan", "/wheel_odom", true});
    const ReadResult got = readAll(r);
    EXPECT_EQ(got.scans.size(), 10u);
    EXPECT_EQ(got.scans[0]->sensorLabel, "/rear/scan");
    EXPECT_EQ(got.odometry.size(), 10u);
  }
  {
    BagReader r(path, {"/front/scan", "", false});  // no odometry: no need to choose
    EXPECT_EQ(r.odomTopic(), "");
    EXPECT_EQ(readAll(r).odometry.size(), 0u);
  }
  const std::string unknown = errorOf([&] { BagReader r(path, {"/scan", "", false}); });
  EXPECT_NE(unknown.find("has no topic '/scan'; its topics: /front/scan (sensor_msgs/LaserScan, 10 messages), "
                         "/odom (nav_msgs/Odometry, 10 messages)"),
            std::string::npos)
      << unknown;
  const std::string wrong = errorOf([&] { BagReader r(path, {"/odom", "", false}); });
  EXPECT_NE(wrong.find("topic '/odom' is nav_msgs/Odometry, not sensor_msgs/LaserScan"), std::string::npos) << wrong;
}

TEST(BagReader, NoOdometryTopicMeansLaserOnlyAndNoScanTopicNoScans)
{
  BagSpec laser_only;
  laser_only.odom_topics.clear();
  BagReader r(writeBag("laser_only", laser_only), {});
  EXPECT_EQ(r.odomTopic(), "");
  EXPECT_EQ(readAll(r).scans.size(), 10u);

  BagSpec odom_only;
  odom_only.scan_topics.clear();
  const std::string path = writeBag("odom_only", odom_only);
  BagReader o(path, {});
  EXPECT_EQ(o.scanTopic(), "");
  EXPECT_EQ(readAll(o).scans.size(), 0u);
  // Through a ScanSource: no scan, and the reason lists the topics.
  auto source = openScanSource(path, {}, CarmenParams{});
  sensor::ScanInput in;
  EXPECT_FALSE(source->next(in));
  EXPECT_EQ(source->noScanReason(""),
            "no sensor_msgs/LaserScan topic in it; its topics: /odom (nav_msgs/Odometry, 10 messages)");
  EXPECT_EQ(source->describe(), "ROS bag " + path + " (no LaserScan topic)");
}

TEST(BagReader, SensorPoseFromTheStaticTransformsOfTheBaseFrame)
{
  BagSpec spec;
  const mrpt::poses::CPose3D mount(0.2, 0, 0.1, 0.5, 0, 0), laser(0.05, 0.02, 0, 0.1, 0, 0);
  spec.tf_static = {transformToRos(mount, "base_link", "mount", ros::Time(kT0)),
                    transformToRos(laser, "mount", "laser", ros::Time(kT0)),
                    transformToRos(mrpt::poses::CPose3D(9, 9, 0, 0, 0, 0), "map", "odom", ros::Time(kT0))};
  BagReader r(writeBag("tf", spec), {});
  const mrpt::poses::CPose3D expected = mount + laser;
  EXPECT_NEAR((r.sensorPose() - expected).norm(), 0, 1e-9);
  EXPECT_EQ(r.sensorPoseSource(), "/tf_static 'base_link' -> 'laser'");
  const ReadResult got = readAll(r);
  EXPECT_NEAR((got.scans[0]->sensorPose - expected).norm(), 0, 1e-9);
  EXPECT_NEAR(got.scans[0]->sensorPose.yaw(), 0.6, 1e-6);  // the message's float angles
}

TEST(BagReader, ATruncatedBagIsNamed)
{
  for (const double keep : {0.6, 0.99})  // cut in the chunks, cut in the index
  {
    const std::string path = writeBag("truncated", {});
    std::filesystem::resize_file(path, static_cast<uintmax_t>(std::filesystem::file_size(path) * keep));
    const std::string e = errorOf([&] { BagReader r(path, {}); });
    EXPECT_NE(e.find("bag '" + path + "'"), std::string::npos) << e;
    EXPECT_NE(e.find("rosbag reindex"), std::string::npos) << e;
  }
  EXPECT_NE(errorOf([] { BagReader r("/nonexistent/x.bag", {}); }).find("no such file"), std::string::npos);
  // A recording killed before it closed: the file header's index position is still 0.
  const std::string unclosed = writeBag("unclosed", {});
  std::fstream f(unclosed, std::ios::in | std::ios::out | std::ios::binary);
  std::string head(4096, '\0');
  f.read(&head[0], head.size());
  const size_t field = head.find("index_pos=");
  ASSERT_NE(field, std::string::npos);
  f.clear();
  f.seekp(field + 10);
  f.write("\0\0\0\0\0\0\0\0", 8);
  f.close();
  const std::string e = errorOf([&] { BagReader r(unclosed, {}); });
  EXPECT_NE(e.find("has no index: its recording was cut short (`rosbag reindex` rebuilds the index)"), std::string::npos)
      << e;
  const std::string rawlog = std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.rawlog";
  const std::string not_bag = errorOf([&] { BagReader r(rawlog, {}); });
  EXPECT_NE(not_bag.find("is not a ROS bag: it does not start with \"#ROSBAG\""), std::string::npos) << not_bag;
}

TEST(BagReader, ADamagedMessageStopsTheReadingAfterTheGoodOnes)
{
  const std::string path = writeBag("damaged", {});
  // Scan 6 states 2^30 + 1 rays (ROS's deserializer would allocate 4 GiB for it).
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const auto m = scanMessage(6);
  char pattern[8];
  const uint32_t n = kRays;
  std::memcpy(pattern, &n, 4);
  std::memcpy(pattern + 4, &m.ranges[0], 4);
  const size_t at = bytes.find(std::string(pattern, 8));
  ASSERT_NE(at, std::string::npos);
  const uint32_t huge = (1u << 30) + 1;
  std::memcpy(&bytes[at], &huge, 4);
  std::ofstream(path, std::ios::binary) << bytes;

  BagReader r(path, {});
  size_t scans = 0;
  mrpt::obs::CObservation::Ptr obs;
  try
  {
    while (r.next(obs)) scans += bool(std::dynamic_pointer_cast<CObservation2DRangeScan>(obs));
    FAIL() << "the damage went unnoticed";
  }
  catch (const BagError& e)
  {
    EXPECT_EQ(scans, 6u);
    EXPECT_EQ(e.message(), 13u);  // 7 odometry readings and 6 scans before it
    EXPECT_NE(std::string(e.what()).find("message #13 of 20 cannot be read (/scan at"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("runs past the message's"), std::string::npos) << e.what();
  }
}

TEST(BagReader, BagsAreRecognizedByNameOrContent)
{
  const std::string path = writeBag("magic", {});
  const std::string renamed = path + ".data";
  std::filesystem::rename(path, renamed);
  EXPECT_TRUE(isBagFile(renamed));
  EXPECT_TRUE(isBagFile("/nonexistent/x.bag"));
  EXPECT_FALSE(isBagFile(std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.rawlog"));
  auto source = openScanSource(renamed, {}, CarmenParams{});
  EXPECT_NE(source->describe().find("ROS bag"), std::string::npos);
  const std::string disagree =
      errorOf([&] { openScanSource(renamed, ScanSourceOptions{true, "LIDAR", "/scan", ""}, CarmenParams{}); });
  EXPECT_NE(disagree.find("--sensor-label 'LIDAR' and --scan-topic '/scan' disagree"), std::string::npos) << disagree;
  EXPECT_EQ(openScanSource(renamed, ScanSourceOptions{true, "/scan", "", ""}, CarmenParams{})->describe(),
            source->describe());  // the label picks the topic
  EXPECT_THROW(openScanSource(std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.rawlog",
                              ScanSourceOptions{true, "", "/scan", ""}, CarmenParams{}),
               std::runtime_error);
}

TEST(BagReader, ScanSourceTurnsOdometryIntoIncrements)
{
  auto source = openScanSource(writeBag("source", {}), {}, CarmenParams{});
  sensor::ScanInput in;
  std::vector<sensor::ScanInput> inputs;
  while (source->next(in)) inputs.push_back(in);
  ASSERT_EQ(inputs.size(), 10u);
  EXPECT_FALSE(inputs[0].odometry_increment);
  // 2 m/s, scans 0.1 s apart; the readings come 0.05 s before each scan. At the first scan
  // one reading was known (taken as it is), from the second on the readings are extrapolated
  // to the scans' times (OdometryIntegrator).
  ASSERT_TRUE(inputs[1].odometry_increment);
  EXPECT_NEAR(inputs[1].odometry_increment->x(), 0.3, 1e-9);
  for (size_t k = 2; k < inputs.size(); k++)
  {
    ASSERT_TRUE(inputs[k].odometry_increment) << k;
    EXPECT_NEAR(inputs[k].odometry_increment->x(), 0.2, 1e-9) << k;
  }
  EXPECT_EQ(source->stats().odometry, 10u);
  EXPECT_EQ(source->describe(), "ROS bag " + std::filesystem::temp_directory_path().string() +
                                    "/swslam_bag_source.bag (scans /scan, sensor pose identity (no /tf_static "
                                    "transform from 'base_link' to 'laser'), odometry /odom)");
}

TEST(BagReader, AScanWithoutHeaderStampTakesItsBagTime)
{
  const std::string path = (std::filesystem::temp_directory_path() / "swslam_bag_unstamped.bag").string();
  {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    for (int k = 0; k < 3; k++)
    {
      sensor_msgs::LaserScan m = scanMessage(k);
      m.header.stamp = ros::Time();
      bag.write("/scan", ros::Time(kT0 + 0.1 * k), m);
    }
  }
  BagReader r(path, {});
  const ReadResult got = readAll(r);
  ASSERT_EQ(got.scans.size(), 3u);
  EXPECT_NEAR(mrpt::Clock::toDouble(got.scans[2]->timestamp), kT0 + 0.2, 1e-6);
}

namespace
{
std::string fileBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/** The bag `path` with the 4 bytes at `at(bytes)` set to `value`, written beside it. */
std::string withU32(const std::string& path, const std::string& name, const std::function<size_t(const std::string&)>& at,
                    uint32_t value)
{
  std::string bytes = fileBytes(path);
  std::memcpy(&bytes[at(bytes)], &value, 4);
  const std::string out = path + "." + name + ".bag";
  std::ofstream(out, std::ios::binary) << bytes;
  return out;
}
}  // namespace

TEST(BagReader, AChunkStating4GiBStopsTheReadingAfterTheMessagesBeforeIt)
{
  // librosbag reserved the 4 GiB and asserted (exit 134, nothing written).
  for (const auto compression : {rosbag::compression::BZ2, rosbag::compression::LZ4})
  {
    BagSpec spec;
    spec.scans = 40;
    spec.compression = compression;
    const std::string path = writeBag("chunk4g", spec);
    // The third chunk's header: its "size" field (uncompressed bytes).
    const uint64_t third = readRos1BagLayout(path).chunks.at(2).pos;
    const auto third_size = [&](const std::string& b) { return b.find("size=", third) + 5; };
    BagReader r(withU32(path, "size", third_size, 0xFFFFFFF0), {});
    size_t scans = 0;
    mrpt::obs::CObservation::Ptr obs;
    const std::string e = errorOf([&] {
      while (r.next(obs)) scans += bool(std::dynamic_pointer_cast<CObservation2DRangeScan>(obs));
    });
    EXPECT_GE(scans, 2u);  // the first two chunks
    EXPECT_LT(scans, 40u);
    EXPECT_NE(e.find("cannot be read (/"), std::string::npos) << e;
    EXPECT_NE(e.find("the bag is damaged: chunk 3 of "), std::string::npos) << e;
    EXPECT_NE(e.find("it states 4294967280 bytes uncompressed, more than the 268435456 a chunk may hold"),
              std::string::npos)
        << e;
  }
}

TEST(BagReader, ARecordLengthPastTheFileIsNamedBeforeLibrosbagSeesIt)
{
  BagSpec spec;
  spec.compression = rosbag::compression::BZ2;
  const std::string path = writeBag("length4g", spec);
  const uint64_t second = readRos1BagLayout(path).chunks.at(1).pos;
  const auto second_chunk_data_length = [&](const std::string& b) {
    uint32_t header_len;
    std::memcpy(&header_len, &b[second], 4);
    return second + 4 + header_len;
  };
  const std::string e =
      errorOf([&] { BagReader r(withU32(path, "length", second_chunk_data_length, 0xFFFFFFF0), {}); });
  EXPECT_NE(e.find("is damaged: the record at byte "), std::string::npos) << e;
  EXPECT_NE(e.find("(a chunk): its data states 4294967280 bytes, but "), std::string::npos) << e;
}

TEST(BagReader, AFlippedBitInTheFileHeaderIsNamedAsDamageWithoutALineFromTheLibrary)
{
  // One flip read "a truncated bag has lost its index" after the library's "Received an
  // invalid TCPROS header". Every bit of the file header record but its padding.
  const std::string path = writeBag("flip", {});
  const std::string good = fileBytes(path);
  uint32_t header_len;
  std::memcpy(&header_len, &good[13], 4);
  const std::string flipped = path + ".flipped.bag";
  size_t named = 0;
  for (size_t byte = 13; byte < 13 + 8 + header_len; byte++)
    for (int bit = 0; bit < 8; bit++)
    {
      std::string bytes = good;
      bytes[byte] = char(bytes[byte] ^ (1 << bit));
      std::ofstream(flipped, std::ios::binary) << bytes;
      testing::internal::CaptureStderr();
      const std::string e = errorOf([&] {
        BagReader r(flipped, {});
        readAll(r);
      });
      const std::string said = testing::internal::GetCapturedStderr();
      EXPECT_EQ(said, "") << "byte " << byte << " bit " << bit;
      if (e.empty()) continue;
      named++;
      EXPECT_NE(e.find("damaged"), std::string::npos) << "byte " << byte << " bit " << bit << ": " << e;
    }
  EXPECT_GT(named, 8 * (8 + header_len) / 2);
}

TEST(BagReader, ARawlogsFanComesBackToTheBit)
{
  // A LaserScan holds its angles as float32: the aperture rebuilt from angle_increment x (n - 1)
  // was off in its last bits, and a symmetric fan's middle by as much, which turned the scan by
  // 1e-8 rad: the bag run's trajectory differed from the rawlog run's (by micrometres).
  for (const auto& [rays, degrees] : {std::pair{1081, 270.0}, std::pair{181, 180.0}, std::pair{361, 240.0}})
  {
    CObservation2DRangeScan scan;
    scan.aperture = static_cast<float>(degrees * M_PI / 180);
    scan.resizeScan(rays);
    for (int i = 0; i < rays; i++) scan.setScanRange(i, 1.0f + 0.001f * i), scan.setScanRangeValidity(i, true);
    scan.maxRange = 30;
    scan.sensorPose = mrpt::poses::CPose3D(0.4, 0, 0.5, 0, 0, 0);
    const CObservation2DRangeScan back = scanFromRos(scanToRos(scan, "laser"), "/scan", scan.sensorPose);
    EXPECT_EQ(back.aperture, scan.aperture) << rays;
    EXPECT_EQ(back.sensorPose.yaw(), 0.0) << rays;
  }
}

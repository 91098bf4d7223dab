// rawlog -> bag: what the bag reader gives back is what the rawlog reader gives.
#include <swslam/io/rawlog2bag.h>
#include <swslam/io/ros2_bag_writer.h>
#include <swslam/io/scan_source.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::io;

namespace
{
std::string tempPath(const std::string& name)
{
  return (std::filesystem::temp_directory_path() / ("swslam_rawlog2bag_" + name)).string();
}

/** 20 scans of a mounted scanner (and 5 of another), odometry before each scan. */
void writeRawlog(const std::string& path)
{
  mrpt::io::CFileGZOutputStream f(path);
  auto arch = mrpt::serialization::archiveFrom(f);
  std::mt19937 rng(3);
  for (int k = 0; k < 20; k++)
  {
    const mrpt::poses::CPose2D pose(0.1 * k, 0.02 * k, 0.01 * k);
    mrpt::obs::CObservationOdometry odo;
    odo.sensorLabel = "ODOMETRY";
    odo.timestamp = mrpt::Clock::fromDouble(500 + 0.1 * k);
    odo.odometry = pose;
    arch << odo;
    auto scan = test::simulateObservation(test::roomWorld(), pose, 181, M_PI, 30, 0.01, rng);
    scan.sensorLabel = "LIDAR";
    scan.timestamp = odo.timestamp;
    scan.sensorPose = mrpt::poses::CPose3D(0.3, -0.1, 0.2, 0.1, 0, 0);
    arch << scan;
    if (k % 4 == 0)
    {
      scan.sensorLabel = "OTHER";
      arch << scan;
    }
  }
}

std::vector<sensor::ScanInput> readInputs(const std::string& path)
{
  auto source = openScanSource(path, {}, CarmenParams{});
  std::vector<sensor::ScanInput> out;
  sensor::ScanInput in;
  while (source->next(in)) out.push_back(in);
  return out;
}
}  // namespace

class Rawlog2BagCompressed : public testing::TestWithParam<std::string>
{
};

TEST_P(Rawlog2BagCompressed, TheBagReadsBackAsTheRawlog)
{
  // A ROS 1 bag of each chunk compression; a ROS 2 bag as one .mcap file and as a rosbag2 folder.
  const std::string kind = GetParam();
  const bool ros2 = kind == "mcap" || kind == "rosbag2";
  const std::string rawlog = tempPath("in_" + kind + ".rawlog");
  const std::string bag = tempPath("out_" + kind + (kind == "rosbag2" ? "" : ros2 ? ".mcap" : ".bag"));
  std::filesystem::remove_all(bag);
  writeRawlog(rawlog);
  Rawlog2BagOptions opts;
  opts.input = rawlog;
  opts.output = bag;
  if (!ros2) opts.compression = kind;
  const Rawlog2BagStats stats = rawlog2bag(opts);
  EXPECT_EQ(stats.sensor_label, "LIDAR");
  EXPECT_EQ(stats.scans, 20u);
  EXPECT_EQ(stats.odometry, 20u);
  EXPECT_EQ(stats.other_labels.at("OTHER"), 5u);
  EXPECT_NE(formatRawlog2BagStats(stats, opts).find("skipped 5 scans of sensor 'OTHER'"), std::string::npos);

  const auto want = readInputs(rawlog), got = readInputs(bag);
  ASSERT_EQ(got.size(), want.size());
  for (size_t k = 0; k < got.size(); k++)
  {
    const auto& a = *want[k].observation;
    const auto& b = *got[k].observation;
    EXPECT_EQ(b.sensorLabel, "/scan");
    EXPECT_NEAR(mrpt::Clock::toDouble(b.timestamp), mrpt::Clock::toDouble(a.timestamp), 1e-6);
    EXPECT_NEAR((b.sensorPose - a.sensorPose).norm(), 0, 1e-6) << k;  // through /tf_static
    EXPECT_NEAR(b.sensorPose.yaw(), a.sensorPose.yaw(), 1e-6) << k;
    EXPECT_EQ(b.aperture, a.aperture);  // to the bit: the fan from its float32 angle_min and angle_max
    ASSERT_EQ(b.getScanSize(), a.getScanSize());
    for (size_t i = 0; i < a.getScanSize(); i++)
    {
      ASSERT_EQ(b.getScanRangeValidity(i), a.getScanRangeValidity(i)) << k << " " << i;
      if (a.getScanRangeValidity(i)) ASSERT_EQ(b.getScanRange(i), a.getScanRange(i)) << k << " " << i;
    }
    ASSERT_EQ(bool(got[k].odometry_increment), bool(want[k].odometry_increment)) << k;
    if (want[k].odometry_increment)
      EXPECT_NEAR((*got[k].odometry_increment - *want[k].odometry_increment).norm(), 0, 1e-6) << k;
  }
}

INSTANTIATE_TEST_SUITE_P(Rawlog2Bag, Rawlog2BagCompressed, testing::Values("none", "bz2", "lz4", "mcap", "rosbag2"));

TEST(Rawlog2Bag, TheFormatIsChosenByTheOptionOrTheOutputsName)
{
  EXPECT_FALSE(isRos2Output("x/run.bag"));
  EXPECT_TRUE(isRos2Output("x/run.mcap"));
  EXPECT_TRUE(isRos2Output("x/run"));  // a rosbag2 folder
  const std::string rawlog = tempPath("in_format.rawlog"), folder = tempPath("format_rosbag2");
  writeRawlog(rawlog);
  std::filesystem::remove_all(folder);
  Rawlog2BagOptions opts;
  opts.input = rawlog;
  opts.output = tempPath("format_forced.bag");
  opts.format = "ros2";  // a ROS 2 bag whatever the name: a rosbag2 folder named .bag
  std::filesystem::remove_all(opts.output);
  rawlog2bag(opts);
  EXPECT_TRUE(std::filesystem::exists(opts.output + "/metadata.yaml"));
  EXPECT_TRUE(std::filesystem::exists(opts.output + "/swslam_rawlog2bag_format_forced_0.mcap"));
  opts.format = "ros3";
  EXPECT_THROW(rawlog2bag(opts), std::invalid_argument);
  opts.format = "";
  opts.output = folder;
  opts.compression = "bz2";  // ROS 1 only
  EXPECT_THROW(rawlog2bag(opts), std::invalid_argument);
  opts.compression = "none";
  std::filesystem::create_directories(folder);
  std::ofstream(folder + "/notes.txt") << "mine\n";
  EXPECT_NE(test::errorOf([&] { rawlog2bag(opts); }).find("exists and is not a rosbag2 folder (no metadata.yaml)"),
            std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(folder + "/notes.txt"));
  EXPECT_FALSE(std::filesystem::exists(folder + ".partial"));
}

TEST(Rawlog2Bag, NothingIsWrittenWithoutScans)
{
  const std::string rawlog = tempPath("in2.rawlog"), bag = tempPath("none.bag"), folder = tempPath("none_rosbag2");
  writeRawlog(rawlog);
  std::filesystem::remove(bag);
  std::filesystem::remove_all(folder);
  Rawlog2BagOptions opts;
  opts.input = rawlog;
  opts.sensor_label = "NOPE";
  for (const std::string& out : {bag, folder})
  {
    opts.output = out;
    EXPECT_THROW(rawlog2bag(opts), std::runtime_error);
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_FALSE(std::filesystem::exists(out + ".partial"));
  }
  opts.output = bag;
  opts.sensor_label = "";
  opts.compression = "zip";
  EXPECT_THROW(rawlog2bag(opts), std::invalid_argument);
}

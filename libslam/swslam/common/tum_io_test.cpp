#include <swslam/common/atomic_file.h>
#include <swslam/common/tum_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "test_support.h"

TEST(TumIo, RoundTripKeepsPosesAndTimes)
{
  const auto dir = swslam::test::tempDir("tum");
  std::vector<swslam::common::StampedPose> poses = {{0.5, {1, 2, 0.3}}, {1.25, {-3, 4.5, -2.9}},
                                            {1700000000.125, {0, 0, M_PI - 1e-6}}};
  swslam::common::writeTum(dir + "/a.tum", poses);
  const auto back = swslam::common::readTum(dir + "/a.tum");
  ASSERT_EQ(back.size(), poses.size());
  for (size_t i = 0; i < poses.size(); i++)
  {
    EXPECT_NEAR(back[i].t, poses[i].t, 1e-6);
    EXPECT_NEAR(back[i].pose.x(), poses[i].pose.x(), 1e-6);
    EXPECT_NEAR(back[i].pose.y(), poses[i].pose.y(), 1e-6);
    EXPECT_NEAR(std::remainder(back[i].pose.phi() - poses[i].pose.phi(), 2 * M_PI), 0, 1e-6);
  }
}

TEST(TumIo, AnyFiniteTimeWritesALineThatReadsBack)
{
  // "%.6f" of 1e308 is 316 characters: a fixed buffer cut the line (found by fuzzing,
  // tests/fuzz/regressions/tum_io).
  const auto dir = swslam::test::tempDir("tum_long");
  const std::vector<swslam::common::StampedPose> poses = {{1e308, {-1e9, 2, 1}}, {-1e307, {3, 4, 0}}};
  swslam::common::writeTum(dir + "/long.tum", poses);
  const auto back = swslam::common::readTum(dir + "/long.tum");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_DOUBLE_EQ(back[0].t, 1e308);
  EXPECT_DOUBLE_EQ(back[0].pose.x(), -1e9);
  EXPECT_DOUBLE_EQ(back[1].t, -1e307);
}

namespace
{
/** readTum's error on `path` ("" if it reads). */
std::string readError(const std::string& path)
{
  try
  {
    swslam::common::readTum(path);
  }
  catch (const std::runtime_error& e)
  {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(TumIo, MalformedLineNamesTheLine)
{
  const auto dir = swslam::test::tempDir("tum_bad");
  std::ofstream(dir + "/b.tum") << "# header\n0 0 0 0 0 0 0 1\n1 2 three 0 0 0 0 1\n";
  const std::string why = readError(dir + "/b.tum");
  EXPECT_NE(why.find("line 3"), std::string::npos) << why;
}

TEST(TumIo, AQuaternionThatIsNotUnitIsAnErrorNamingTheLine)
{
  // All zeros read as yaw 0, silently; a quaternion written with 4 decimals still loads.
  const auto dir = swslam::test::tempDir("tum_quat");
  std::ofstream(dir + "/q.tum") << "0 0 0 0 0 0 0.3827 0.9239\n1 1 0 0 0 0 0 0\n";
  const std::string why = readError(dir + "/q.tum");
  EXPECT_NE(why.find("line 2: quaternion (0 0 0 0) has norm 0"), std::string::npos) << why;
  std::ofstream(dir + "/ok.tum") << "0 0 0 0 0 0 0.3827 0.9239\n";
  EXPECT_NEAR(swslam::common::readTum(dir + "/ok.tum").at(0).pose.phi(), M_PI / 4, 1e-3);
}

TEST(TumIo, APositionBeyondAMillionKilometresIsAnErrorNamingTheLine)
{
  // Finite, so it read; then the ATE's sum of squares overflowed to inf.
  const auto dir = swslam::test::tempDir("tum_huge");
  std::ofstream(dir + "/h.tum") << "0 1e9 -1e9 0 0 0 0 1\n1 1e160 0 0 0 0 0 1\n";
  const std::string why = readError(dir + "/h.tum");
  EXPECT_NE(why.find("line 2: position x = 1e+160 m is beyond 1e+09 m"), std::string::npos) << why;
}

TEST(AtomicFile, FailedWriterLeavesPreviousFileIntact)
{
  const auto dir = swslam::test::tempDir("atomic");
  const auto path = dir + "/out.txt";
  swslam::common::writeTextAtomically(path, "first");
  EXPECT_THROW(swslam::common::writeAtomically(path,
                                       [](const std::string& tmp) {
                                         std::ofstream(tmp) << "half";
                                         throw std::runtime_error("interrupted");
                                       }),
               std::runtime_error);
  std::ifstream f(path);
  std::string content;
  f >> content;
  EXPECT_EQ(content, "first");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

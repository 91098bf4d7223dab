#include <swslam/io/rawlog_reader.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::io;

namespace
{
/** Reads `path` to its end: the items read, and the error that stopped the reading (none
 * at a clean end). */
std::pair<size_t, std::optional<RawlogError>> readAll(const std::string& path)
{
  RawlogReader r(path);
  RawlogItem item;
  size_t read = 0;
  try
  {
    while (r.next(item)) read++;
  }
  catch (const RawlogError& e)
  {
    return {read, e};
  }
  return {read, std::nullopt};
}

mrpt::obs::CObservation2DRangeScan::Ptr makeScan(int k)
{
  std::mt19937 rng(k);
  auto o = std::make_shared<mrpt::obs::CObservation2DRangeScan>(
      test::simulateObservation(test::roomWorld(), {0.1 * k, 0, 0}, 181, M_PI, 30, 0.01, rng));
  o->timestamp = mrpt::Clock::fromDouble(100.0 + 0.1 * k);
  return o;
}

/** Observation-only rawlog: scans interleaved with odometry. */
void writeObservationRawlog(const std::string& path, int n, bool gz)
{
  auto write = [&](auto& f) {
    auto arch = mrpt::serialization::archiveFrom(f);
    for (int k = 0; k < n; k++)
    {
      arch << *makeScan(k);
      mrpt::obs::CObservationOdometry odo;
      odo.odometry = mrpt::poses::CPose2D(0.1 * k, 0, 0);
      odo.timestamp = mrpt::Clock::fromDouble(100.05 + 0.1 * k);
      arch << odo;
    }
  };
  if (gz)
  {
    mrpt::io::CFileGZOutputStream f(path);
    write(f);
  }
  else
  {
    mrpt::io::CFileOutputStream f(path);
    write(f);
  }
}

size_t countScans(RawlogReader& r)
{
  size_t scans = 0;
  RawlogItem item;
  while (r.next(item))
    if (std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(item.observation)) scans++;
  return scans;
}
}  // namespace

TEST(RawlogReader, ReadsObservationOnlyRawlogsPlainAndGzip)
{
  const auto dir = test::tempDir("rawlog_obs");
  for (bool gz : {false, true})
  {
    const auto path = dir + (gz ? "/a.rawlog" : "/b.rawlog");
    writeObservationRawlog(path, 10, gz);
    RawlogReader r(path);
    RawlogItem item;
    for (int k = 0; k < 10; k++)
    {
      ASSERT_TRUE(r.next(item));
      auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(item.observation);
      ASSERT_TRUE(scan);
      EXPECT_NEAR(mrpt::Clock::toDouble(scan->timestamp), 100.0 + 0.1 * k, 1e-6);
      ASSERT_TRUE(r.next(item));
      EXPECT_TRUE(std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(item.observation));
    }
    EXPECT_FALSE(r.next(item));
    EXPECT_EQ(r.entriesRead(), 20u);
  }
}

TEST(RawlogReader, ReadsActionSensoryFramePairs)
{
  const auto dir = test::tempDir("rawlog_sf");
  const auto path = dir + "/sf.rawlog";
  {
    mrpt::io::CFileGZOutputStream f(path);
    auto arch = mrpt::serialization::archiveFrom(f);
    for (int k = 0; k < 5; k++)
    {
      mrpt::obs::CActionCollection acts;
      mrpt::obs::CActionRobotMovement2D mv;
      mrpt::obs::CActionRobotMovement2D::TMotionModelOptions opts;
      mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0.01), opts);
      acts.insert(mv);
      arch << acts;
      mrpt::obs::CSensoryFrame sf;
      sf.insert(makeScan(k));
      arch << sf;
    }
  }
  RawlogReader r(path);
  RawlogItem item;
  int scans = 0, actions = 0;
  while (r.next(item))
  {
    if (item.odometry_increment)
    {
      actions++;
      EXPECT_NEAR(item.odometry_increment->poseChange->getMeanVal().x(), 0.1, 1e-9);
    }
    if (std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(item.observation)) scans++;
  }
  EXPECT_EQ(scans, 5);
  EXPECT_EQ(actions, 5);
}

TEST(RawlogReader, TruncatedFileGivesTheEntryIndexAndKeepsWhatWasRead)
{
  const auto dir = test::tempDir("rawlog_trunc");
  const auto path = dir + "/full.rawlog", cut = dir + "/cut.rawlog";
  writeObservationRawlog(path, 10, false);
  const auto size = std::filesystem::file_size(path);
  std::filesystem::copy_file(path, cut);
  std::filesystem::resize_file(cut, size / 2 + 7);  // cut in the middle of an entry
  const auto [read, error] = readAll(cut);
  ASSERT_TRUE(error) << "a truncated rawlog must not look like a clean end";
  {
    const RawlogError& e = *error;
    EXPECT_EQ(e.entry(), read);
    EXPECT_GE(read, 8u);
    EXPECT_NE(std::string(e.what()).find("entry #" + std::to_string(read)), std::string::npos)
        << e.what();
    // MRPT's messages, without its call-stack backtraces (30 lines of addresses).
    EXPECT_NE(std::string(e.what()).find("Cannot read"), std::string::npos)
        << e.what();
    EXPECT_EQ(std::string(e.what()).find("backtrace"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

TEST(RawlogReader, CorruptBytesAreAnErrorNotACrash)
{
  const auto dir = test::tempDir("rawlog_corrupt");
  const auto path = dir + "/c.rawlog";
  writeObservationRawlog(path, 6, false);
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(std::filesystem::file_size(path) / 2));
    for (int k = 0; k < 64; k++) f.put(static_cast<char>(0xA5));
  }
  RawlogReader r(path);
  EXPECT_THROW(countScans(r), RawlogError);
}

TEST(RawlogReader, MissingFileIsAClearError)
{
  EXPECT_THROW(RawlogReader("/nonexistent/dir/x.rawlog"), std::runtime_error);
}

TEST(RawlogReader, ReadsMrptsBundledMalagaDataset)
{
  const std::string path =
      std::string(SWSLAM_MRPT_DATASETS) + "/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "mrpt-common not installed: " << path;
  RawlogReader r(path);
  EXPECT_EQ(countScans(r), 225u);  // rawlog-edit --info: 449 objects, 224 actions + 225 frames
}

TEST(RawlogReader, AScanWithAHugeRayCountIsAnErrorBeforeAnyAllocation)
{
  // A flipped byte in a scan's ray count made MRPT allocate 9 bytes per claimed ray (a
  // segfault or minutes of paging for 2^32): the count is checked first.
  const auto dir = test::tempDir("rawlog_rays");
  const auto path = dir + "/r.rawlog";
  writeObservationRawlog(path, 4, false);
  std::string bytes;
  {
    std::ifstream f(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(f), {});
  }
  const std::string scan_class = "mrpt::obs::CObservation2DRangeScan";
  const size_t third = bytes.find(scan_class, bytes.find(scan_class, bytes.find(scan_class) + 1) + 1);
  ASSERT_NE(third, std::string::npos);
  const size_t count_at = third - 1 + 164;  // entry start + the fixed fields before the count
  const uint32_t rays = static_cast<uint32_t>(bytes[count_at] & 0xff) | (bytes[count_at + 1] & 0xff) << 8;
  ASSERT_EQ(rays, makeScan(2)->getScanSize()) << "the layout changed";
  const uint32_t huge = 200000000;  // 1.8 GB for MRPT
  for (int b = 0; b < 4; b++) bytes[count_at + b] = static_cast<char>(huge >> (8 * b));
  std::ofstream(path, std::ios::binary) << bytes;

  const auto [read, error] = readAll(path);
  ASSERT_TRUE(error) << "a corrupt ray count must be an error";
  {
    const RawlogError& e = *error;
    EXPECT_EQ(e.entry(), 4u);  // scan, odometry, scan, odometry, then the third scan
    EXPECT_EQ(read, 4u);
    EXPECT_NE(std::string(e.what()).find("a scan of 200000000 rays"), std::string::npos) << e.what();
  }
}

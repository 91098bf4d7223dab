#include <swslam/io/rawlog_reader.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <sys/resource.h>
#include <sys/wait.h>

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

TEST(RawlogReader, AScanMountedBeyondTheBoundIsAnErrorNamingTheEntryAndThePose)
{
  // A scan mounted at x = 1e30 corrupted the search's grid in threaded swslam; 1e4 took 20 s
  // and 1.2 GB. Each is refused where the reader meets it, after the scans before it.
  const auto dir = test::tempDir("rawlog_mount");
  for (const double x : {1e30, 1e4, 51.0})
  {
    const auto path = dir + "/m.rawlog";
    {
      mrpt::io::CFileOutputStream f(path);
      auto arch = mrpt::serialization::archiveFrom(f);
      for (int k = 0; k < 3; k++)
      {
        auto scan = makeScan(k);
        if (k == 2) scan->sensorPose = mrpt::poses::CPose3D(x, 0, 0.2, 0, 0, 0);
        arch << *scan;
      }
    }
    RawlogReader r(path);
    RawlogItem item;
    EXPECT_TRUE(r.next(item));
    EXPECT_TRUE(r.next(item));
    try
    {
      r.next(item);
      FAIL() << x << ": a scan mounted beyond the bound must be an error";
    }
    catch (const RawlogError& e)
    {
      EXPECT_EQ(e.entry(), 2u);
      EXPECT_EQ(r.entriesRead(), 2u);
      const std::string what = e.what();
      EXPECT_NE(what.find("entry #2 (at byte "), std::string::npos) << what;
      EXPECT_NE(what.find("sensor mounted at"), std::string::npos) << what;
      EXPECT_NE(what.find("beyond the 50 m"), std::string::npos) << what;
    }
    EXPECT_THROW(r.next(item), RawlogError) << "and again on the next call";
  }
}

namespace
{
/** An action/sensory-frame rawlog of `n` pairs (plain), its scans labelled "FRONT_LASER";
 * returns each entry's byte offset. */
std::vector<uint64_t> writeActionFrameRawlog(const std::string& path, int n)
{
  std::vector<uint64_t> offsets;
  mrpt::io::CFileOutputStream f(path);
  auto arch = mrpt::serialization::archiveFrom(f);
  for (int k = 0; k < n; k++)
  {
    mrpt::obs::CActionCollection acts;
    mrpt::obs::CActionRobotMovement2D mv;
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions opts;
    mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0.01), opts);
    acts.insert(mv);
    offsets.push_back(f.getPosition());
    arch << acts;
    mrpt::obs::CSensoryFrame sf;
    auto scan = makeScan(k);
    scan->sensorLabel = "FRONT_LASER";
    sf.insert(scan);
    offsets.push_back(f.getPosition());
    arch << sf;
  }
  return offsets;
}

std::string readBytes(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

/** Writes `value` (little-endian) over the 4 bytes at `at`. */
void overwriteU32(std::string& bytes, size_t at, uint32_t value)
{
  for (int b = 0; b < 4; b++) bytes[at + b] = static_cast<char>(value >> (8 * b));
}

/** Where the serialized object of class `name` that starts at or after `from` begins (its
 * class tag), and where its fields begin (after the name and the version byte). */
std::pair<size_t, size_t> objectAt(const std::string& bytes, const std::string& name, size_t from)
{
  const size_t at = bytes.find(name, from);
  if (at == std::string::npos) throw std::logic_error("no " + name + " in the rawlog: the layout changed");
  return {at - 1, at + name.size() + 1};
}

struct DamagedRawlog
{
  std::string path;
  std::vector<uint64_t> offsets;  ///< of its entries
};

/** The action/sensory-frame rawlog of 4 pairs, `value` written over the 4 bytes at
 * `field_at(its bytes, its entries' offsets)`. */
DamagedRawlog damagedRawlog(
    const std::string& name, uint32_t value,
    const std::function<size_t(const std::string&, const std::vector<uint64_t>&)>& field_at)
{
  DamagedRawlog r{test::tempDir("rawlog_damage") + "/" + name + ".rawlog", {}};
  r.offsets = writeActionFrameRawlog(r.path, 4);
  std::string bytes = readBytes(r.path);
  overwriteU32(bytes, field_at(bytes, r.offsets), value);
  std::ofstream(r.path, std::ios::binary) << bytes;
  return r;
}

const std::string kOverBudget = "needed more than 1 GB of memory";

struct DamagedRead
{
  size_t items = 0;
  std::optional<RawlogError> error;
  double seconds = 0;
};

DamagedRead readDamaged(const std::string& path)
{
  const auto t0 = std::chrono::steady_clock::now();
  const auto [read, error] = readAll(path);
  return {read, error, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()};
}

/** The damaged rawlog gives a RawlogError quickly and with bounded memory, saying one of
 * `whys`. */
void expectBoundedDamage(const DamagedRead& r, const std::vector<std::string>& whys)
{
  ASSERT_TRUE(r.error) << "the damage went unnoticed";
  const std::string what = r.error->what();
  EXPECT_TRUE(std::any_of(whys.begin(), whys.end(), [&](const std::string& why) { return what.find(why) != std::string::npos; }))
      << what;
  // A bound, not a benchmark: 0.5 s at most when measured in Release; 3-8 s under
  // AddressSanitizer, where the child fills its budget with small allocations first.
  EXPECT_LT(r.seconds, 20.0) << what;
  rusage self{}, children{};
  getrusage(RUSAGE_SELF, &self);
  getrusage(RUSAGE_CHILDREN, &children);
  EXPECT_LT(self.ru_maxrss, 1 << 20) << "the test process grew past 1 GB (KB: " << self.ru_maxrss << ")";
  // The decoder's budget: 1 GB beyond its size at the fork (at most the test process's
  // peak), plus what it touches in one period of the watch of its resident memory.
  EXPECT_LT(children.ru_maxrss, self.ru_maxrss + (1 << 20) + (128 << 10))
      << "a decoder grew past its 1 GB budget (KB: " << children.ru_maxrss << ", the test process's peak "
      << self.ru_maxrss << ")";
  std::cerr << "read in " << r.seconds << " s, decoder's peak " << children.ru_maxrss / 1024 << " MB: " << what << "\n";
}

/** The damaged rawlog gives a RawlogError at entry `entry` (offset `offset`) after the `items`
 * good ones, quickly and with bounded memory, saying one of `whys`. */
void expectDamageAt(const DamagedRead& r, size_t items, size_t entry, uint64_t offset,
                    const std::vector<std::string>& whys)
{
  ASSERT_TRUE(r.error) << "the damage went unnoticed";
  const std::string what = r.error->what();
  EXPECT_EQ(r.items, items) << what;
  EXPECT_EQ(r.error->entry(), entry) << what;
  EXPECT_NE(what.find("entry #" + std::to_string(entry) + " (at byte " + std::to_string(offset) + ")"),
            std::string::npos)
      << what;
  expectBoundedDamage(r, whys);
}
}  // namespace

// Damage MRPT trusted: each count or length below made it allocate gigabytes (or crash). The
// decoder's child process reaches its memory budget instead, and the entry is named.
TEST(RawlogReader, ADamagedActionCountIsAnErrorNamingTheEntry)
{
  const auto r = damagedRawlog("actions", 0xFFFFFFFFu, [](const std::string& bytes, const auto& offsets) {
    return objectAt(bytes, "mrpt::obs::CActionCollection", offsets[4]).second;  // the number of actions
  });
  // Before it: 2 actions and 2 scans.
  expectDamageAt(readDamaged(r.path), 4, 4, r.offsets[4], {kOverBudget});
}

TEST(RawlogReader, ADamagedObservationCountOfASensoryFrameIsAnErrorNamingTheEntry)
{
  const auto r = damagedRawlog("frames", 0x7FFFFFFFu, [](const std::string& bytes, const auto& offsets) {
    return objectAt(bytes, "mrpt::obs::CSensoryFrame", offsets[5]).second;  // the number of observations
  });
  expectDamageAt(readDamaged(r.path), 5, 5, r.offsets[5], {kOverBudget});
}

TEST(RawlogReader, ADamagedLabelLengthIsAnErrorNamingTheEntry)
{
  const auto r = damagedRawlog("label", 0xF0000000u, [](const std::string& bytes, const auto& offsets) {
    const size_t label = bytes.find("FRONT_LASER", offsets[5]);
    if (label > offsets[6] || bytes[label - 4] != 11) throw std::logic_error("the label's length field moved");
    return label - 4;
  });
  expectDamageAt(readDamaged(r.path), 5, 5, r.offsets[5], {kOverBudget});
}

TEST(RawlogReader, ADamagedRayCountInsideASensoryFrameIsAnErrorNamingTheEntry)
{
  // The check of a top-level scan's ray count does not see into a sensory frame.
  const auto r = damagedRawlog("rays", 0xFFFFFFF0u, [](const std::string& bytes, const auto& offsets) {
    const size_t count_at = objectAt(bytes, "mrpt::obs::CObservation2DRangeScan", offsets[5]).first + 164;
    if (count_at > offsets[6] || (static_cast<uint32_t>(bytes[count_at] & 0xff) | (bytes[count_at + 1] & 0xff) << 8) != 181)
      throw std::logic_error("the scan's layout changed");
    return count_at;
  });
  expectDamageAt(readDamaged(r.path), 5, 5, r.offsets[5], {kOverBudget, "the decoder crashed with SIG"});
}

TEST(RawlogReader, TheFuzzersDamagedCountsAreTheBudgetsError)
{
  // tests/fuzz/mrpt-findings/rawlog_reader: rawlogs of a few hundred bytes found by the fuzzer
  // (doc/reliability.md), on which MRPT asks for 0.4 to 7.5 GB, at once or bit by bit.
  const std::string dir = std::string(SWSLAM_SOURCE_DIR) + "/tests/fuzz/mrpt-findings/rawlog_reader/";
  const std::vector<std::string> over_budget{kOverBudget};
  // The 7.5 GB is an aligned_alloc, which returns null under the address-space limit and MRPT
  // writes there; under AddressSanitizer it is the budget's report.
  const std::vector<std::string> or_crash{kOverBudget, "the decoder crashed with SIGSEGV"};
  const std::vector<std::pair<std::string, std::vector<std::string>>> findings{
      {"action-collection-442MB.rawlog", over_budget},
      {"action-collection-rss-4GB.rawlog", over_budget},
      {"motion-particles-960MB.rawlog", over_budget},
      {"scan-label-string-1.9GB.rawlog", over_budget},
      {"scan-rays-7.5GB-other-namespace.rawlog", or_crash}};
  for (const auto& [file, whys] : findings)
  {
    SCOPED_TRACE(file);
    expectBoundedDamage(readDamaged(dir + file), whys);
  }
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), ptrdiff_t(findings.size()));
}

TEST(RawlogReader, AnActionEntryThatCrashesMrptIsAnErrorNamingTheEntry)
{
  // tests/data/crashing_action.rawlog (291 bytes): a CObservationOdometry (entry 0, 103 bytes),
  // then a CActionCollection written by MRPT 2.5 with one byte changed from 0 to 1: byte 69 of
  // the entry, the first field of its CActionRobotMovement2D (after its version byte 7). Found
  // by flipping each byte of the entry: any value 1-255 in bytes 69-72 makes MRPT's
  // CActionRobotMovement2D::serializeFrom die with SIGSEGV.
  constexpr uint64_t kCrashingActionOffset = 103;
  const std::string path = std::string(SWSLAM_SOURCE_DIR) + "/tests/data/crashing_action.rawlog";
  const auto r = readDamaged(path);
  expectDamageAt(r, 1, 1, kCrashingActionOffset, {"the decoder crashed with SIGSEGV"});
}

TEST(RawlogReader, EverythingReturnedBeforeTheDamageStaysValid)
{
  const std::string path = damagedRawlog("valid", 0x7FFFFFFFu, [](const std::string& bytes, const auto& offsets) {
                             return objectAt(bytes, "mrpt::obs::CSensoryFrame", offsets[5]).second;
                           }).path;
  std::vector<RawlogItem> items;
  {
    RawlogReader r(path);
    RawlogItem item;
    EXPECT_THROW(
        while (r.next(item)) items.push_back(item), RawlogError);
    EXPECT_THROW(r.next(item), RawlogError) << "the reader goes on failing";
  }
  ASSERT_EQ(items.size(), 5u);
  for (int k = 0; k < 2; k++)
  {
    ASSERT_TRUE(items[2 * k].odometry_increment);
    EXPECT_NEAR(items[2 * k].odometry_increment->poseChange->getMeanVal().x(), 0.1, 1e-12);
    auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(items[2 * k + 1].observation);
    ASSERT_TRUE(scan);
    EXPECT_EQ(scan->sensorLabel, "FRONT_LASER");
    EXPECT_EQ(scan->getScanSize(), 181u);
    EXPECT_EQ(scan->timestamp, makeScan(k)->timestamp);
  }
}

TEST(RawlogReader, AReaderDestroyedEarlyLeavesNoProcess)
{
  const auto path = test::tempDir("rawlog_early") + "/a.rawlog";
  writeObservationRawlog(path, 200, false);
  {
    RawlogReader r(path);
    RawlogItem item;
    ASSERT_TRUE(r.next(item));
  }
  errno = 0;
  EXPECT_TRUE(waitpid(-1, nullptr, WNOHANG) < 0 && errno == ECHILD);
}

TEST(RawlogReader, ACutGzipStreamIsAnErrorEvenAtAnEntryBoundary)
{
  // A .gz cut short used to look like the clean end if the cut fell between entries.
  const auto dir = test::tempDir("rawlog_gzcut");
  const auto path = dir + "/a.rawlog";
  writeObservationRawlog(path, 40, true);
  std::string bytes = readBytes(path);
  bytes.resize(bytes.size() - 6);  // the trailer: every entry is there, but the stream is cut
  std::ofstream(path, std::ios::binary) << bytes;
  const auto [read, error] = readAll(path);
  ASSERT_TRUE(error) << "a truncated gzip rawlog must not look like a clean end";
  EXPECT_EQ(read, 80u);
  EXPECT_NE(std::string(error->what()).find("the gzip stream is cut short"), std::string::npos) << error->what();
  // The damage is after the 80 entries, not in the last of them.
  EXPECT_EQ(error->entry(), 80u) << error->what();
  EXPECT_NE(std::string(error->what()).find("entry #80 "), std::string::npos) << error->what();
}

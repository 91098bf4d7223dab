// End to end: the `swslam` app's code on the bundled lake-short log; every output loads back.
#include <swslam/app/offline_run.h>
#include <swslam/app/output_folder.h>
#include <swslam/app/run_outputs.h>
#include <swslam/common/tum_io.h>
#include <swslam/eval/report.h>
#include <swslam/graph/io.h>
#include <swslam/io/rawlog_reader.h>
#include <swslam/map/files.h>
#include <swslam/map/octomap_export.h>

#include <gtest/gtest.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <octomap/OcTree.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <set>
#include <fstream>
#include <sstream>

#include "test_support.h"

using namespace swslam;
using namespace swslam::app;

namespace
{
/** lake-short, deterministic, no render, into DIR/out. */
OfflineRunOptions quickLakeRun(const std::string& dir)
{
  const std::string src = SWSLAM_SOURCE_DIR;
  OfflineRunOptions o;
  o.config = src + "/config/default.ini";
  o.input = src + "/datasets/lake-short/lake-short.rawlog";
  o.output = dir + "/out";
  o.deterministic = true;
  o.render = false;
  return o;
}
}  // namespace

TEST(OfflineRun, LakeShortEndToEndWithinTheAteBoundAndEveryOutputLoads)
{
  const std::string src = SWSLAM_SOURCE_DIR, dir = test::tempDir("offline_lake");
  OfflineRunOptions o;
  o.config = src + "/config/default.ini";
  o.input = src + "/datasets/lake-short/lake-short.rawlog";
  o.ground_truth = src + "/datasets/lake-short/lake-short.gt.tum";
  o.output = dir + "/out";  // does not exist yet
  o.deterministic = true;
  std::ostringstream out, err;
  ASSERT_EQ(runOffline(o, out, err), kExitOk) << err.str();
  EXPECT_NE(out.str().find("| ATE (rmse) |"), std::string::npos) << out.str();

  // The input still reads (nothing wrote to it), and the trajectory has one pose per scan.
  io::RawlogReader reader(o.input);
  io::RawlogItem item;
  size_t scans = 0;
  while (reader.next(item))
    scans += item.observation && item.observation->GetRuntimeClass() ==
                                     CLASS_ID(mrpt::obs::CObservation2DRangeScan);
  const auto trajectory = common::readTum(o.output + "/trajectory.tum");
  EXPECT_EQ(trajectory.size(), scans);
  const auto eval = eval::evaluateTrajectory(trajectory, common::readTum(o.ground_truth), 0.01);
  EXPECT_LT(eval.ate.position.rmse, 0.10);
  EXPECT_LT(eval.rpe_segment.translation.rmse, 0.05);

  const graph::PoseGraph graph = graph::loadGraph(o.output + "/graph.graph");
  EXPECT_EQ(common::readTum(o.output + "/keyframes.tum").size(), graph.nodeCount());
  EXPECT_GT(graph.edgeCount(), graph.nodeCount());

  const auto grid = map::readGridmap(o.output + "/map.gridmap.gz");
  EXPECT_GT(map::countOccupied(grid, 0.65), 100u);
  octomap::OcTree tree(0.1);
  ASSERT_TRUE(tree.readBinary(o.output + "/map.bt"));
  EXPECT_GT(tree.getNumLeafNodes(), 100u);
  for (const char* png : {"map.png", "render.png"})
  {
    mrpt::img::CImage img;
    ASSERT_TRUE(img.loadFromFile(o.output + "/" + png)) << png;
    EXPECT_GT(img.getWidth(), 10u) << png;
  }
  EXPECT_TRUE(std::filesystem::is_regular_file(o.output + "/map.yaml"));
  EXPECT_TRUE(std::filesystem::is_regular_file(o.output + "/map.pgm"));

  std::ifstream csv(o.output + "/stats.csv");
  std::string line;
  size_t rows = 0;
  std::getline(csv, line);
  EXPECT_EQ(line.rfind("scan,timestamp,source,", 0), 0u) << line;
  while (std::getline(csv, line)) rows++;
  EXPECT_EQ(rows, scans);
  std::filesystem::remove_all(dir);
}

TEST(OfflineRun, BadConfigOrInputIsAUsageErrorThatWritesNothing)
{
  const std::string src = SWSLAM_SOURCE_DIR, dir = test::tempDir("offline_bad");
  {
    std::ofstream ini(dir + "/bad.ini");
    ini << "[tracking]\nkeyframe_translaton = 0.5\n";
  }
  OfflineRunOptions o;
  o.config = dir + "/bad.ini";
  o.input = src + "/datasets/lake-short/lake-short.rawlog";
  o.output = dir + "/out";
  std::ostringstream out, err;
  EXPECT_EQ(runOffline(o, out, err), kExitUsage);
  EXPECT_NE(err.str().find("keyframe_translaton"), std::string::npos) << err.str();
  EXPECT_FALSE(std::filesystem::exists(o.output));

  {  // each key valid alone, the pair not: still a usage error, not an abort
    std::ofstream ini(dir + "/bad.ini");
    ini << "[tracking]\ndense_max_index_gap = 40\n[loop_closure]\nmin_index_gap = 30\n";
  }
  err.str("");
  EXPECT_EQ(runOffline(o, out, err), kExitUsage);
  EXPECT_NE(err.str().find("dense_max_index_gap"), std::string::npos) << err.str();
  EXPECT_FALSE(std::filesystem::exists(o.output));

  o.config = src + "/config/default.ini";
  o.input = dir + "/missing.rawlog";
  err.str("");
  EXPECT_EQ(runOffline(o, out, err), kExitUsage);
  EXPECT_NE(err.str().find("missing.rawlog"), std::string::npos) << err.str();
  std::filesystem::remove_all(dir);
}

TEST(OfflineRun, TruncatedRawlogStillWritesWhatWasMapped)
{
  const std::string src = SWSLAM_SOURCE_DIR, dir = test::tempDir("offline_trunc");
  // The first third of the (gzip) rawlog: the stream breaks off mid-entry.
  const std::string full = src + "/datasets/lake-short/lake-short.rawlog", cut = dir + "/cut.rawlog";
  std::ifstream in(full, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(cut, std::ios::binary).write(bytes.data(), bytes.size() / 3);
  OfflineRunOptions o;
  o.config = src + "/config/default.ini";
  o.input = cut;
  o.output = dir + "/out";
  o.deterministic = true;
  o.render = false;
  std::ostringstream out, err;
  EXPECT_EQ(runOffline(o, out, err), kExitInputError);
  EXPECT_NE(err.str().find("input stopped after"), std::string::npos) << err.str();
  const auto trajectory = common::readTum(o.output + "/trajectory.tum");
  EXPECT_GT(trajectory.size(), 300u);
  EXPECT_GT(map::countOccupied(map::readGridmap(o.output + "/map.gridmap.gz"), 0.65), 50u);
  std::filesystem::remove_all(dir);
}

TEST(OfflineRun, ARunThatTracksNoScanSaysWhyAndWritesNothing)
{
  const std::string dir = test::tempDir("offline_empty");
  OfflineRunOptions o = quickLakeRun(dir);
  o.sensor_label = "NO_SUCH_LASER";
  std::ostringstream out, err;
  EXPECT_EQ(runOffline(o, out, err), kExitInputError);
  // The labels the log has, with their counts.
  EXPECT_NE(err.str().find("no scan of sensor 'NO_SUCH_LASER'; the log's laser scans are of '"), std::string::npos)
      << err.str();
  EXPECT_NE(err.str().find("(2461 scans)"), std::string::npos) << err.str();
  EXPECT_FALSE(std::filesystem::exists(o.output + "/trajectory.tum"));
  EXPECT_FALSE(std::filesystem::exists(o.output + "/graph.graph"));

  // A rawlog of odometry only.
  o.sensor_label.clear();
  o.input = dir + "/odometry-only.rawlog";
  {
    mrpt::io::CFileGZOutputStream f(o.input);
    auto arch = mrpt::serialization::archiveFrom(f);
    for (int k = 0; k < 3; k++)
    {
      auto odo = mrpt::obs::CObservationOdometry::Create();
      odo->timestamp = mrpt::Clock::fromDouble(100.0 + k);
      odo->odometry = mrpt::poses::CPose2D(0.1 * k, 0, 0);
      arch << *odo;
    }
  }
  err.str("");
  EXPECT_EQ(runOffline(o, out, err), kExitInputError);
  EXPECT_NE(err.str().find("no laser scan"), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("3 odometry readings"), std::string::npos) << err.str();
  EXPECT_FALSE(std::filesystem::exists(o.output + "/trajectory.tum"));
  std::filesystem::remove_all(dir);
}

TEST(OfflineRun, AGroundTruthThatDoesNotOverlapTheRunIsAnErrorAfterTheOutputs)
{
  const std::string src = SWSLAM_SOURCE_DIR, dir = test::tempDir("offline_gt");
  auto truth = common::readTum(src + "/datasets/lake-short/lake-short.gt.tum");
  for (auto& p : truth) p.t += 1e6;  // a day and a half later
  common::writeTum(dir + "/later.tum", truth);
  OfflineRunOptions o = quickLakeRun(dir);
  o.ground_truth = dir + "/later.tum";
  o.max_scans = 200;
  std::ostringstream out, err;
  EXPECT_EQ(runOffline(o, out, err), kExitInputError);
  EXPECT_NE(err.str().find("ground truth: "), std::string::npos) << err.str();
  EXPECT_EQ(common::readTum(o.output + "/trajectory.tum").size(), 200u);
  std::filesystem::remove_all(dir);
}

TEST(OfflineRun, ARerunReplacesEveryOutputOfThePreviousRunAndTwoRunsDoNotShareAFolder)
{
  const std::string dir = test::tempDir("offline_rerun");
  OfflineRunOptions o = quickLakeRun(dir);
  o.max_scans = 300;
  {
    OutputFolder other(o.output);  // a second run holding the folder
    std::ostringstream out, err;
    EXPECT_EQ(runOffline(o, out, err), kExitUsage);
    EXPECT_NE(err.str().find("another run is writing into it"), std::string::npos) << err.str();
  }
  // A previous run's output, and a temporary file of a run killed while writing.
  // (render.png and a resumed run's change report are outputs this run does not write.)
  for (const char* old : {"render.png", "changes.md", ".graph.tmp99.graph"}) std::ofstream(o.output + "/" + old) << "old";
  std::ostringstream out, err;
  ASSERT_EQ(runOffline(o, out, err), kExitOk) << err.str();
  EXPECT_NE(err.str().find("removed 1 temporary file(s)"), std::string::npos) << err.str();
  // Exactly this run's outputs: the old render (not written without --render) and change
  // report (not written by a run that resumed nothing) are gone.
  std::set<std::string> files, expected;
  for (const auto& e : std::filesystem::directory_iterator(o.output))
    if (e.path().filename() != ".swslam.lock") files.insert(e.path().filename().string());
  for (const auto& f : runOutputFiles())
    if (f != "render.png" && f != "changes.md" && f != "changes.png") expected.insert(f);
  EXPECT_EQ(files, expected);
  std::filesystem::remove_all(dir);
}

namespace
{
/** The first `n` scans (and the odometry among them) of lake-short into `path`, each
 * observation passed to `edit` first with the index of the scan it is or precedes. */
void writeEditedLake(const std::string& path, size_t n,
                     const std::function<void(size_t, mrpt::obs::CObservation&)>& edit)
{
  io::RawlogReader reader(std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.rawlog");
  mrpt::io::CFileGZOutputStream f(path);
  auto arch = mrpt::serialization::archiveFrom(f);
  io::RawlogItem item;
  size_t scans = 0;
  while (scans < n && reader.next(item))
  {
    if (!item.observation) continue;
    edit(scans, *item.observation);
    arch << *item.observation;
    scans += std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(item.observation) ? 1 : 0;
  }
}
/** lake-short's first `n` scans restamped by `stamp` (the scan's index, its time). */
void writeRestampedLake(const std::string& path, size_t n, const std::function<double(size_t, double)>& stamp)
{
  writeEditedLake(path, n, [&](size_t k, mrpt::obs::CObservation& o) {
    o.timestamp = mrpt::Clock::fromDouble(stamp(k, mrpt::Clock::toDouble(o.timestamp)));
  });
}
/** lake-short's first `n` scans, the rays of the scans k with blind(k) all invalid (no return). */
void writeBlindedLake(const std::string& path, size_t n, const std::function<bool(size_t)>& blind)
{
  writeEditedLake(path, n, [&](size_t k, mrpt::obs::CObservation& o) {
    if (auto* scan = dynamic_cast<mrpt::obs::CObservation2DRangeScan*>(&o); scan && blind(k))
      for (size_t i = 0; i < scan->getScanSize(); i++) scan->setScanRangeValidity(i, false);
  });
}
}  // namespace

TEST(OfflineRun, ALogWithoutAValidRayIsAnErrorAndOneWithSomeSaysHowMany)
{
  const std::string dir = test::tempDir("offline_blind");
  OfflineRunOptions o = quickLakeRun(dir);
  o.input = dir + "/blind.rawlog";
  writeBlindedLake(o.input, 40, [](size_t) { return true; });
  std::ostringstream out, err;
  EXPECT_EQ(runOffline(o, out, err), kExitInputError);
  EXPECT_NE(err.str().find("none of its 40 scans tracked had a valid ray"), std::string::npos) << err.str();
  EXPECT_FALSE(std::filesystem::exists(o.output + "/map.gridmap.gz")) << "no empty map";
  EXPECT_FALSE(std::filesystem::exists(o.output + "/trajectory.tum"));

  writeBlindedLake(o.input, 40, [](size_t k) { return k >= 10 && k < 20; });
  std::ostringstream out_some, err_some;
  EXPECT_EQ(runOffline(o, out_some, err_some), kExitOk) << err_some.str();
  EXPECT_NE(err_some.str().find("10 of the 40 scans tracked had no valid ray"), std::string::npos) << err_some.str();
  EXPECT_EQ(common::readTum(o.output + "/trajectory.tum").size(), 40u);
  std::filesystem::remove_all(dir);
}

TEST(OfflineRun, ARealtimeFactorBelowZeroOrNotANumberIsAUsageError)
{
  const std::string dir = test::tempDir("offline_rate");
  OfflineRunOptions o = quickLakeRun(dir);
  for (const double rate : {-1.0, std::nan("")})
  {
    o.realtime_factor = rate;
    std::ostringstream out, err;
    EXPECT_EQ(runOffline(o, out, err), kExitUsage) << rate;
    EXPECT_NE(err.str().find("--realtime-factor must be a finite number, at least 0"), std::string::npos) << err.str();
    EXPECT_FALSE(std::filesystem::exists(o.output));
  }
  std::filesystem::remove_all(dir);
}

TEST(OfflineRun, AScanStampedBeyondTheYear2200IsSkippedAndSaid)
{
  const std::string dir = test::tempDir("offline_stamp_range");
  OfflineRunOptions o = quickLakeRun(dir);
  o.input = dir + "/one-bad.rawlog";
  writeRestampedLake(o.input, 60, [](size_t k, double t) { return k == 30 ? 1e12 : t; });
  std::ostringstream out, err;
  EXPECT_EQ(runOffline(o, out, err), kExitOk) << err.str();
  EXPECT_NE(err.str().find("skipped input scan 30: timestamp 1e+12 s is outside 1970-2200 (milliseconds rather than "
                           "seconds?)"),
            std::string::npos)
      << err.str();
  EXPECT_EQ(common::readTum(o.output + "/trajectory.tum").size(), 59u);
  std::filesystem::remove_all(dir);
}

TEST(OfflineRun, ALogWhoseStampsMostlyCannotBeUsedIsAnInputError)
{
  // Stamps in microseconds became 0 in MRPT's clock (a CARMEN log converted before the
  // converter refused such logs): one scan was used, and the run said nothing was wrong.
  const std::string dir = test::tempDir("offline_stamp_us");
  OfflineRunOptions o = quickLakeRun(dir);
  o.input = dir + "/us.rawlog";
  writeRestampedLake(o.input, 60, [](size_t, double t) { return t * 1e6; });
  std::ostringstream out, err;
  EXPECT_EQ(runOffline(o, out, err), kExitInputError);
  EXPECT_NE(err.str().find("59 of the 60 scans read were skipped for their timestamps"), std::string::npos) << err.str();
  std::filesystem::remove_all(dir);
}

TEST(OfflineRun, ThrottledScansAreOneInNOfTheLogAndTheSummarySaysSo)
{
  const std::string dir = test::tempDir("offline_throttle");
  OfflineRunOptions o = quickLakeRun(dir);
  o.max_scans = 40;  // scans used
  std::ostringstream out0, err0;
  ASSERT_EQ(runOffline(o, out0, err0), kExitOk) << err0.str();
  const auto every = common::readTum(o.output + "/trajectory.tum");
  o.throttle_scans = 4;
  o.max_scans = 10;
  std::ostringstream out, err;
  ASSERT_EQ(runOffline(o, out, err), kExitOk) << err.str();
  const auto kept = common::readTum(o.output + "/trajectory.tum");
  ASSERT_EQ(kept.size(), 10u);
  for (size_t k = 0; k < kept.size(); k++) EXPECT_DOUBLE_EQ(kept[k].t, every[4 * k].t) << k;
  EXPECT_NE(out.str().find("one scan in 4"), std::string::npos) << out.str();
  // A warning names the scan by its index in the log.
  o.input = dir + "/one-bad.rawlog";
  writeRestampedLake(o.input, 60, [](size_t k, double t) { return k == 32 ? 1e12 : t; });
  std::ostringstream out_bad, err_bad;
  EXPECT_EQ(runOffline(o, out_bad, err_bad), kExitOk) << err_bad.str();
  EXPECT_NE(err_bad.str().find("skipped input scan 32: timestamp 1e+12 s"), std::string::npos) << err_bad.str();
  o.throttle_scans = 0;
  std::ostringstream out_zero, err_zero;
  EXPECT_EQ(runOffline(o, out_zero, err_zero), kExitUsage);
  EXPECT_NE(err_zero.str().find("N must be at least 1"), std::string::npos) << err_zero.str();
  std::filesystem::remove_all(dir);
}

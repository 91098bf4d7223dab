// swslam-live end to end against the SCIP 2.0 emulator (tests/scip) serving the lake-short
// scenario over loopback TCP at 40 Hz: MRPT's CHokuyoURG driver, the recorder and the system.
#include "scip/scip_emulator.h"
#include "scip/scip_sim_source.h"

#include <swslam/app/live_run.h>
#include <swslam/app/offline_run.h>
#include <swslam/app/output_folder.h>
#include <swslam/common/tum_io.h>
#include <swslam/eval/report.h>
#include <swslam/io/rawlog_reader.h>
#include <swslam/sim/scenario.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <thread>
#include <tuple>
#include <vector>

#include "log_cut_support.h"
#include "test_support.h"

using namespace swslam;
using namespace swslam::app;
using std::chrono::milliseconds;

namespace
{
const std::string kSrc = SWSLAM_SOURCE_DIR;

scip::SimScanSource lakeSource()
{
  return scip::SimScanSource(sim::loadScenario(kSrc + "/datasets/scenarios/lake-short.ini"));
}

scip::EmulatorOptions options(uint16_t port = 0)
{
  scip::EmulatorOptions o;
  o.port = port;
  o.history = 5000;
  return o;
}

/** A sensor config for the emulator, with lake-short's sensor mounting. */
std::string sensorIni(const std::string& dir, uint16_t port)
{
  const std::string path = dir + "/sensor.ini";
  std::ofstream(path) << "[LASER_2D]\ndriver = CHokuyoURG\nsensorLabel = HOKUYO_UTM\nIP_DIR = 127.0.0.1\n"
                      << "PORT_DIR = " << port << "\npose_x = 0.4\npose_z = 0.5\n";
  return path;
}

LiveRunOptions liveOptions(const std::string& dir, uint16_t port, double duration)
{
  LiveRunOptions o;
  o.config = kSrc + "/config/default.ini";
  o.sensor_config = sensorIni(dir, port);
  o.output = dir + "/out";
  o.duration = duration;
  o.save_period = 4;
  o.status = false;
  o.render = false;
  return o;
}

size_t countScans(const std::string& rawlog)
{
  io::RawlogReader reader(rawlog);
  io::RawlogItem item;
  size_t n = 0;
  while (reader.next(item)) n += item.observation != nullptr;
  return n;
}

/** ATE of a run's trajectory against the emulator's ground truth, pose i <-> sent scan i. */
double ateAgainstSent(const std::string& trajectory, const std::vector<scip::SentScan>& sent,
                      const scip::SimScanSource& source)
{
  const auto est = common::readTum(trajectory);
  std::vector<common::StampedPose> gt;
  for (size_t i = 0; i < est.size() && i < sent.size(); i++) gt.push_back({est[i].t, source.pose(sent[i].k)});
  return eval::evaluateTrajectory(est, gt, 1e-6).ate.position.rmse;
}
}  // namespace

TEST(LiveRun, MapsFromTheEmulatorRecordsEveryScanAndReplaysIdentically)
{
  const std::string dir = test::tempDir("live_main");
  const auto source = lakeSource();
  scip::ScipEmulator emu(source, options());
  LiveRunOptions o = liveOptions(dir, emu.port(), 20);
  o.deterministic = true;  // so that the replay must give the same trajectory, bit for bit
  std::ostringstream out, err;
  std::thread stopper([&] {
    // The sensor goes quiet before the app stops: everything it sent must be recorded.
    std::this_thread::sleep_for(milliseconds(18000));
    emu.stop();
  });
  const int code = runLive(o, out, err);
  stopper.join();
  ASSERT_EQ(code, 0) << err.str();
  const auto sent = emu.sentScans();
  ASSERT_GT(sent.size(), 600u) << err.str();
  const std::string recording = o.output + "/recording.rawlog";
  EXPECT_EQ(countScans(recording), sent.size()) << out.str();
  EXPECT_EQ(common::readTum(o.output + "/trajectory.tum").size(), sent.size());
  EXPECT_LT(ateAgainstSent(o.output + "/trajectory.tum", sent, source), 0.10);

  OfflineRunOptions replay;
  replay.config = o.config;
  replay.input = recording;
  replay.output = dir + "/replay";
  replay.deterministic = true;
  replay.render = false;
  std::ostringstream rout, rerr;
  ASSERT_EQ(runOffline(replay, rout, rerr), kExitOk) << rerr.str();
  std::ifstream a(o.output + "/trajectory.tum"), b(replay.output + "/trajectory.tum");
  std::stringstream sa, sb;
  sa << a.rdbuf();
  sb << b.rdbuf();
  EXPECT_EQ(sa.str(), sb.str());
  std::filesystem::remove_all(dir);
}

TEST(LiveRun, SurvivesADroppedConnectionAndAnUnpluggedSensor)
{
  const std::string dir = test::tempDir("live_drop");
  const auto source = lakeSource();
  auto opts = options();
  opts.faults.drop_after_scans = 120;  // the sensor closes the first connection after 3 s
  auto emu = std::make_unique<scip::ScipEmulator>(source, opts);
  const uint16_t port = emu->port();
  LiveRunOptions o = liveOptions(dir, port, 16);
  std::ostringstream out, err;
  size_t sent_before_unplug = 0;
  std::thread operator_thread([&] {
    std::this_thread::sleep_for(milliseconds(6000));
    sent_before_unplug = emu->stats().scans_sent;
    emu.reset();  // unplugged: connection and port closed
    std::this_thread::sleep_for(milliseconds(2500));
    emu = std::make_unique<scip::ScipEmulator>(source, options(port));  // plugged back in
    std::this_thread::sleep_for(milliseconds(5000));
    emu->stop();
  });
  const int code = runLive(o, out, err);
  operator_thread.join();
  ASSERT_EQ(code, 0) << err.str();
  const size_t sent_after = emu->stats().scans_sent;
  const size_t recorded = countScans(o.output + "/recording.rawlog");
  EXPECT_GT(sent_before_unplug, 150u);
  EXPECT_GT(sent_after, 100u) << err.str();
  // Nothing received is lost; at most the scan cut by each disconnection is missing.
  EXPECT_GE(recorded + 3, sent_before_unplug + sent_after) << out.str();
  EXPECT_EQ(common::readTum(o.output + "/trajectory.tum").size(), recorded);
  EXPECT_NE(err.str().find("waiting for the sensor"), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("receiving scans again"), std::string::npos) << err.str();
  EXPECT_NE(out.str().find("connection(s)"), std::string::npos);
  // No status line (status = false, the app's --quiet), although the run lasts past its 10 s period.
  EXPECT_EQ(err.str().find("scans/s"), std::string::npos) << err.str();
  std::filesystem::remove_all(dir);
}

TEST(LiveRun, MalformedRepliesAreReportedAndTheRunSurvives)
{
  const std::string dir = test::tempDir("live_faults");
  const auto source = lakeSource();
  auto opts = options();
  opts.faults.scans[40] = scip::Fault::BadChecksum;
  opts.faults.scans[60] = scip::Fault::TruncatedLine;
  opts.faults.scans[80] = scip::Fault::WrongEcho;
  scip::ScipEmulator emu(source, opts);
  LiveRunOptions o = liveOptions(dir, emu.port(), 6);
  std::ostringstream out, err;
  ASSERT_EQ(runLive(o, out, err), 0) << err.str();
  const size_t recorded = countScans(o.output + "/recording.rawlog");
  EXPECT_GT(recorded, 150u);
  EXPECT_NE(err.str().find("sensor driver:"), std::string::npos) << err.str();  // the truncated scan
  EXPECT_EQ(common::readTum(o.output + "/trajectory.tum").size(), recorded);
  std::filesystem::remove_all(dir);
}

TEST(LiveRun, BadTimingOptionsAreErrorsBeforeAnyConnection)
{
  const std::string dir = test::tempDir("live_bad_options");
  for (const auto& [stall, save, duration] :
       std::vector<std::tuple<double, double, double>>{{0, 30, 1},
                                                       {1e300, 30, 1},
                                                       {std::nan(""), 30, 1},
                                                       {2, -1, 1},
                                                       {2, 30, std::numeric_limits<double>::infinity()}})
  {
    LiveRunOptions o = liveOptions(dir, 1, 1);  // port 1: nothing listens, nothing is tried
    o.stall_timeout = stall;
    o.save_period = save;
    o.duration = duration;
    std::ostringstream out, err;
    EXPECT_EQ(runLive(o, out, err), kExitUsage) << stall << " " << save << " " << duration;
    EXPECT_NE(err.str().find("must be"), std::string::npos) << err.str();
    EXPECT_FALSE(std::filesystem::exists(o.output)) << "an output folder was made";
  }
  std::filesystem::remove_all(dir);
}

TEST(LiveRun, ABadSensorSectionLeavesThePreviousRunsOutputs)
{
  const std::string dir = test::tempDir("live_bad_sensor");
  LiveRunOptions o = liveOptions(dir, 1, 1);
  std::ofstream(o.sensor_config) << "[LASER_2D]\ndriver = CSickLaserUSB\n";  // not a Hokuyo
  std::filesystem::create_directories(o.output);
  std::ofstream(o.output + "/summary.md") << "a previous run\n";
  std::ostringstream out, err;
  EXPECT_EQ(runLive(o, out, err), kExitUsage);
  EXPECT_NE(err.str().find("CSickLaserUSB"), std::string::npos) << err.str();
  EXPECT_TRUE(std::filesystem::exists(o.output + "/summary.md")) << "the previous outputs were removed";
  std::filesystem::remove_all(dir);
}

TEST(LiveRun, ASensorThatNeverAnswersLeavesThePreviousRunsOutputsAsTheyWere)
{
  // The previous run's outputs (and recording) were cleared before the sensor was tried.
  const std::string dir = test::tempDir("live_never_answered");
  LiveRunOptions o = liveOptions(dir, 1, 1);  // port 1: nothing listens
  std::filesystem::create_directories(o.output);
  const std::vector<std::string> previous{"summary.md", "trajectory.tum", "recording.rawlog", "map.png"};
  for (const std::string& f : previous) std::ofstream(o.output + "/" + f) << "a previous run's " << f << "\n";
  std::ostringstream out, err;
  EXPECT_EQ(runLive(o, out, err), kExitInputError);
  EXPECT_NE(err.str().find("the sensor never answered"), std::string::npos) << err.str();
  EXPECT_NE(out.str().find("nothing written in " + o.output + "/ (a previous run's outputs are kept)"),
            std::string::npos)
      << out.str();
  size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(o.output))
    files += e.path().filename() != OutputFolder::kLockFile;
  EXPECT_EQ(files, previous.size()) << "a file was added or removed";
  for (const std::string& f : previous)
  {
    std::ifstream in(o.output + "/" + f);
    std::string text;
    std::getline(in, text);
    EXPECT_EQ(text, "a previous run's " + f);
  }
  std::filesystem::remove_all(dir);
}

TEST(LiveRun, LocalizesOnASavedMapInsteadOfMapping)
{
  // The map: the first 10 s of lake-short (the emulator's scenario) mapped offline, a run folder.
  const std::string dir = test::tempDir("live_localize");
  OfflineRunOptions map;
  map.config = kSrc + "/config/default.ini";
  map.input = test::cutLakeShort(dir + "/first.rawlog", 0, 400);
  map.output = dir + "/map";
  map.deterministic = true;
  map.render = false;
  map.progress = false;
  std::ostringstream mout, merr;
  ASSERT_EQ(runOffline(map, mout, merr), kExitOk) << merr.str();

  const auto source = lakeSource();
  scip::ScipEmulator emu(source, options());
  LiveRunOptions o = liveOptions(dir, emu.port(), 5);
  o.localize = map.output;
  std::ostringstream out, err;
  ASSERT_EQ(runLive(o, out, err), kExitOk) << err.str();
  EXPECT_NE(out.str().find("# swslam-live --localize"), std::string::npos) << out.str();
  const auto sent = emu.sentScans();
  const auto poses = common::readTum(o.output + "/localization.tum");
  ASSERT_GT(poses.size(), 100u) << out.str();
  EXPECT_FALSE(std::filesystem::exists(o.output + "/trajectory.tum"));  // no mapping
  // Every scan received placed (the first relocalized on the map), as the map's first pose
  // sees the emulator's truth; the emulator may have sent one more as the run stopped.
  ASSERT_EQ(poses.size(), countScans(o.output + "/recording.rawlog")) << out.str();
  ASSERT_LE(poses.size(), sent.size());
  const mrpt::poses::CPose2D origin = source.pose(0);
  double worst = 0;
  for (size_t i = 0; i < poses.size(); ++i)
    worst = std::max(worst, (poses[i].pose - ((-origin) + source.pose(sent[i].k))).norm());
  EXPECT_LT(worst, 0.1);
  std::filesystem::remove_all(dir);
}

// CARMEN log conversion end to end, on a small excerpt in the real formats written here.
#include <swslam/common/tum_io.h>
#include <swslam/io/carmen2rawlog.h>
#include <swslam/io/rawlog_reader.h>
#include <swslam/io/scan_source.h>
#include <swslam/sensor/scan.h>

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "test_support.h"

namespace
{
using mrpt::obs::CObservation2DRangeScan;

std::string laserLine(const std::string& label, const std::vector<std::string>& ranges,
                      const std::string& pose, const std::string& ts)
{
  std::ostringstream s;
  s << label << " " << ranges.size();
  for (const auto& r : ranges) s << " " << r;
  s << " " << pose << " " << pose << " " << ts << " pippo " << ts;
  return s.str();
}

/** 180 beams at 2 + 0.01 i metres; `special` overrides some beams. */
std::vector<std::string> ranges180(const std::map<int, std::string>& special)
{
  std::vector<std::string> r;
  for (int i = 0; i < 180; i++)
    r.push_back(special.count(i) ? special.at(i) : std::to_string(2 + 0.01 * i));
  return r;
}

// Line numbers matter: the malformed line is line 8.
std::string excerpt()
{
  std::ostringstream s;
  s << "# synthetic CARMEN excerpt\n"
    << "PARAM robot_frontlaser_offset 0.25 nohost 0\n"
    << "PARAM robot_rearlaser_offset 0.3 nohost 0\n"
    << "ODOM 0 0 0 0.1 0 0 10.00 host 10.00\n"
    << laserLine("FLASER", ranges180({{10, "81.91"}, {20, "0"}, {30, "nan"}}), "1 2 0.1", "10.05")
    << "\nODOM 0.1 0 0 0.1 0 0 10.10 host 10.10\n"
    << laserLine("FLASER", ranges180({{11, "81.91"}}), "1.5 2 0.1", "10.05") << "\n"
    << "FLASER 3 1 2\n"
    << laserLine("FLASER", ranges180({{12, "81.91"}, {13, "81.91"}, {14, "81.91"}}), "2 2 0.2", "0")
    << "\n" << laserLine("RLASER", ranges180({}), "2.5 2 0.2", "10.2") << "\n"
    << "NEFF 12.5\n";
  // ROBOTLASER1: 101 beams from -1.2 rad every 0.02 rad; laser at (0.1, 0.05) on the robot.
  const mrpt::poses::CPose2D robot(3, 4, 0.5), laser = robot + mrpt::poses::CPose2D(0.1, 0.05, 0);
  s << "ROBOTLASER1 0 -1.2 2 0.02 20 0.01 0 101";
  for (int i = 0; i < 101; i++) s << " " << (i == 50 ? "25" : "4");
  s << " 0 " << laser.x() << " " << laser.y() << " " << laser.phi()
    << " 3 4 0.5 0 0 0 0 0 10.3 h 10.3\n";
  s << "RAWLASER1 0 -1.5 3 0.5 30 0.01 0 7 1 2 3 4 5 6 7 0 10.4 h 10.4\n";
  return s.str();
}

std::string writeLog(const std::string& dir, const std::string& text)
{
  const std::string path = dir + "/excerpt.log";
  std::ofstream(path) << text;
  return path;
}

struct Converted
{
  std::vector<swslam::io::CarmenRecord> records;
  std::vector<std::string> warnings;
  swslam::io::CarmenStats stats;
};

Converted convert(const std::string& path, const swslam::io::CarmenParams& params)
{
  Converted c;
  swslam::io::CarmenLogReader reader(path, params,
                                 [&](const std::string& m) { c.warnings.push_back(m); });
  swslam::io::CarmenRecord rec;
  while (reader.next(rec)) c.records.push_back(rec);
  c.stats = reader.stats();
  return c;
}

std::vector<std::shared_ptr<CObservation2DRangeScan>> scansOf(const Converted& c)
{
  std::vector<std::shared_ptr<CObservation2DRangeScan>> out;
  for (const auto& r : c.records)
    if (auto s = std::dynamic_pointer_cast<CObservation2DRangeScan>(r.observation))
      out.push_back(s);
  return out;
}

double toSec(mrpt::Clock::time_point t) { return mrpt::Clock::toDouble(t); }

void expectTimes(const std::vector<std::shared_ptr<CObservation2DRangeScan>>& scans,
                 const std::vector<double>& expected)
{
  ASSERT_EQ(scans.size(), expected.size());
  for (size_t i = 0; i < scans.size(); i++)
    EXPECT_NEAR(toSec(scans[i]->timestamp), expected[i], 1e-6) << "scan " << i;
}

/** Conversion of excerpt() (written into a fresh directory) to out.rawlog and gt.tum there. */
swslam::io::Carmen2RawlogOptions excerptConversion(const std::string& dir_name)
{
  const auto dir = swslam::test::tempDir(dir_name);
  swslam::io::Carmen2RawlogOptions opts;
  opts.input = writeLog(dir, excerpt());
  opts.output = dir + "/out.rawlog";
  opts.ground_truth = dir + "/gt.tum";
  return opts;
}

}  // namespace

TEST(CarmenLog, ConvertsTheExcerpt)
{
  const auto dir = swslam::test::tempDir("carmen_excerpt");
  swslam::io::CarmenParams as_logged;  // the log's own stamps, not repaired
  as_logged.repair_timestamps = false;
  const auto c = convert(writeLog(dir, excerpt()), as_logged);
  EXPECT_EQ(c.stats.scans(), 6u);
  EXPECT_EQ(c.stats.odometry, 2u);
  EXPECT_EQ(c.stats.malformed, 1u);
  EXPECT_EQ(c.stats.first_malformed_line, 8u);
  EXPECT_EQ(c.stats.unknown_messages.at("NEFF"), 1u);
  EXPECT_EQ(std::count_if(c.warnings.begin(), c.warnings.end(),
                          [](const std::string& w) { return w.find(":8: malformed") != w.npos; }),
            1);

  const auto scans = scansOf(c);
  ASSERT_EQ(scans.size(), 6u);
  // Own timestamps, kept as logged: 10.05, 10.05 (duplicate), 0 (zero).
  expectTimes(scans, {10.05, 10.05, 0.0, 10.2, 10.3, 10.4});
  EXPECT_EQ(c.stats.timestamps.at("FLASER").non_increasing, 2u);
  EXPECT_NEAR(toSec(c.records[0].observation->timestamp), 10.0, 1e-6);  // ODOM

  // FLASER: 180 beams span 180 degrees; saturation at 81.91 (5 readings) is "no return".
  const auto& f = *scans[0];
  EXPECT_EQ(f.sensorLabel, "FLASER");
  ASSERT_EQ(f.getScanSize(), 180u);
  EXPECT_NEAR(f.aperture, M_PI, 1e-6);
  EXPECT_NEAR(f.maxRange, 81.91, 1e-4);
  EXPECT_TRUE(f.rightToLeft);
  EXPECT_NEAR(f.getScanRange(5), 2.05, 1e-5);
  EXPECT_TRUE(f.getScanRangeValidity(5));
  EXPECT_FALSE(f.getScanRangeValidity(10));  // 81.91: max range
  EXPECT_FALSE(f.getScanRangeValidity(20));  // 0
  EXPECT_FALSE(f.getScanRangeValidity(30));  // nan
  size_t valid = 0;
  for (size_t i = 0; i < 180; i++) valid += f.getScanRangeValidity(i);
  EXPECT_EQ(valid, 177u);
  EXPECT_NEAR(f.sensorPose.x(), 0.25, 1e-9);  // PARAM robot_frontlaser_offset
  EXPECT_NEAR(f.sensorPose.yaw(), 0, 1e-9);
  EXPECT_EQ(swslam::sensor::scanFromObservation(f).size(), 177u);

  // RLASER: behind the robot, looking back; no saturation, so all readings stay valid.
  const auto& r = *scans[3];
  EXPECT_EQ(r.sensorLabel, "RLASER");
  EXPECT_NEAR(r.sensorPose.x(), -0.3, 1e-9);
  EXPECT_NEAR(std::abs(r.sensorPose.yaw()), M_PI, 1e-9);
  EXPECT_TRUE(r.getScanRangeValidity(0));

  // Reference poses (x y theta) of laser lines with a pose.
  ASSERT_TRUE(c.records[1].reference_pose);
  EXPECT_NEAR(c.records[1].reference_pose->x(), 1, 1e-12);
  EXPECT_NEAR(c.records[1].reference_pose->phi(), 0.1, 1e-12);
}

TEST(CarmenLog, RobotLaserAndRawLaserGeometry)
{
  const auto dir = swslam::test::tempDir("carmen_geometry");
  const auto scans = scansOf(convert(writeLog(dir, excerpt()), swslam::io::CarmenParams()));
  ASSERT_EQ(scans.size(), 6u);
  const auto& rl = *scans[4];
  EXPECT_EQ(rl.sensorLabel, "ROBOTLASER1");
  EXPECT_NEAR(rl.maxRange, 20, 1e-6);      // the line's own maximum_range
  EXPECT_FALSE(rl.getScanRangeValidity(50));  // 25 m >= 20 m
  EXPECT_NEAR(rl.sensorPose.x(), 0.1, 1e-5);
  EXPECT_NEAR(rl.sensorPose.y(), 0.05, 1e-5);
  // Beam i must point at start_angle + i * resolution in the robot frame.
  for (size_t i : {0u, 37u, 100u})
  {
    const double a = rl.sensorPose.yaw() + swslam::sensor::beamAngle(i, 101, rl.aperture);
    EXPECT_NEAR(std::remainder(a - (-1.2 + 0.02 * i), 2 * M_PI), 0, 1e-5) << i;
  }
  const auto& raw = *scans[5];
  EXPECT_EQ(raw.sensorLabel, "RAWLASER1");
  EXPECT_NEAR(raw.aperture, 3.0, 1e-6);
  EXPECT_NEAR(raw.sensorPose.x(), 0.25, 1e-9);  // front offset
  EXPECT_NEAR(raw.sensorPose.yaw(), 0.0, 1e-6);  // -1.5 + 3/2
}

TEST(CarmenLog, RepairLaserOnlyAndParams)
{
  const auto dir = swslam::test::tempDir("carmen_repair");
  swslam::io::CarmenParams p;
  p.repair_timestamps = true;
  p.laser_only = true;
  const std::string text = "PARAM robot_front_laser_max 50.0 nohost 0\n"
                           "PARAM laser_front_laser_fov 100 nohost 0\n" + excerpt();
  const auto c = convert(writeLog(dir, text), p);
  EXPECT_EQ(c.stats.odometry, 0u);
  EXPECT_EQ(c.stats.odometry_dropped, 2u);
  const auto scans = scansOf(c);
  // No positive FLASER period in the log: the repair uses 0.1 s.
  expectTimes(scans, {10.05, 10.15, 10.25, 10.2, 10.3, 10.4});
  EXPECT_EQ(c.stats.timestamps.at("FLASER").repaired, 2u);
  EXPECT_NEAR(c.records[2].raw_timestamp, 0.0, 1e-12);
  EXPECT_NEAR(scans[0]->maxRange, 50, 1e-6);           // PARAM robot_front_laser_max
  EXPECT_NEAR(scans[0]->aperture, 100 * M_PI / 180, 1e-6);  // PARAM laser_front_laser_fov

  p.max_range = 2.5;  // forced: beyond 2.5 m is invalid
  const auto forced = scansOf(convert(writeLog(dir, text), p));
  EXPECT_TRUE(forced[0]->getScanRangeValidity(49));   // 2.49 m
  EXPECT_FALSE(forced[0]->getScanRangeValidity(50));  // 2.50 m
}

TEST(CarmenLog, NegativeTimestampsAreShifted)
{
  const auto dir = swslam::test::tempDir("carmen_negative");
  const auto text = laserLine("FLASER", ranges180({}), "0 0 0", "-0.5") + "\n" +
                    laserLine("FLASER", ranges180({}), "1 0 0", "0.5") + "\n" +
                    "ODOM 0 0 0 0 0 0 -2.0 h -2.0\n";
  const auto c = convert(writeLog(dir, text), swslam::io::CarmenParams());
  // Laser timestamps set the shift; an ODOM one still negative after it is written as 0.
  EXPECT_NEAR(c.stats.timestamp_offset, 0.5, 1e-12);
  EXPECT_EQ(c.stats.timestamps.at("ODOM").negative, 1u);
  EXPECT_NEAR(toSec(c.records.back().observation->timestamp), 0.0, 1e-6);
  const auto scans = scansOf(c);
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_NEAR(toSec(scans[0]->timestamp), 0.0, 1e-6);
  EXPECT_NEAR(toSec(scans[1]->timestamp), 1.0, 1e-6);
}

TEST(CarmenLog, TheRawlogTheGroundTruthAndTheLogMustBeThreeFiles)
{
  auto opts = excerptConversion("carmen_same_file");
  const std::string dir = std::filesystem::path(opts.output).parent_path().string();
  // The ground truth over the rawlog (spelled another way), or either over the log.
  for (const auto& [output, ground_truth] :
       {std::pair{opts.output, dir + "/./sub/../out.rawlog"}, {opts.input, opts.ground_truth}, {opts.output, opts.input}})
  {
    auto o = opts;
    o.output = output;
    o.ground_truth = ground_truth;
    try
    {
      swslam::io::carmen2rawlog(o, [](const std::string&) {});
      FAIL() << output << " " << ground_truth << ": no error";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find("must be different files"), std::string::npos) << e.what();
    }
  }
  EXPECT_FALSE(std::filesystem::exists(opts.output));
  EXPECT_GT(std::filesystem::file_size(opts.input), 0u) << "the log is untouched";
}

TEST(CarmenLog, RawlogRoundTripAndGroundTruth)
{
  auto opts = excerptConversion("carmen_rawlog");
  const auto c = convert(opts.input, opts.params);
  const auto stats = swslam::io::carmen2rawlog(opts, [](const std::string&) {});
  EXPECT_EQ(stats.scans(), 6u);

  swslam::io::RawlogReader reader(opts.output);
  swslam::io::RawlogItem item;
  size_t i = 0;
  while (reader.next(item))
  {
    ASSERT_LT(i, c.records.size());
    const auto& expected = c.records[i++].observation;
    ASSERT_TRUE(item.observation);
    EXPECT_EQ(item.observation->sensorLabel, expected->sensorLabel);
    EXPECT_EQ(item.observation->timestamp, expected->timestamp);
    auto got = std::dynamic_pointer_cast<CObservation2DRangeScan>(item.observation);
    auto want = std::dynamic_pointer_cast<CObservation2DRangeScan>(expected);
    ASSERT_EQ(!got, !want);
    if (!got) continue;
    ASSERT_EQ(got->getScanSize(), want->getScanSize());
    for (size_t k = 0; k < got->getScanSize(); k++)
    {
      EXPECT_EQ(got->getScanRangeValidity(k), want->getScanRangeValidity(k));
      if (want->getScanRangeValidity(k)) EXPECT_EQ(got->getScanRange(k), want->getScanRange(k));
    }
    EXPECT_EQ(got->aperture, want->aperture);
    EXPECT_EQ(got->maxRange, want->maxRange);
    EXPECT_NEAR((got->sensorPose - want->sensorPose).norm(), 0, 1e-9);
  }
  EXPECT_EQ(i, c.records.size());

  const auto gt = swslam::common::readTum(opts.ground_truth);
  ASSERT_EQ(gt.size(), 5u);  // FLASER x3, RLASER, ROBOTLASER1 (RAWLASER has no pose)
  EXPECT_NEAR(gt[0].t, 10.05, 1e-6);
  EXPECT_NEAR(gt[0].pose.x(), 1, 1e-6);
  EXPECT_NEAR(gt[4].pose.x(), 3, 1e-6);
  EXPECT_NEAR(gt[4].pose.phi(), 0.5, 1e-6);
}

TEST(CarmenLog, ReferenceOdometryPrecedesEachScanWithAPose)
{
  auto opts = excerptConversion("carmen_reference_odometry");
  opts.reference_odometry = true;
  // Needs laser-only (no ODOM lines mixed in) and repaired timestamps (the third FLASER is
  // stamped 0: its reading would be dropped as out of order and the motion come out wrong).
  for (const auto& [laser_only, repair] : {std::pair{false, true}, {true, false}, {false, false}})
  {
    opts.params.laser_only = laser_only;
    opts.params.repair_timestamps = repair;
    EXPECT_THROW(swslam::io::carmen2rawlog(opts, [](const std::string&) {}), std::invalid_argument);
    EXPECT_FALSE(std::filesystem::exists(opts.output));
  }
  opts.params.laser_only = true;
  opts.params.repair_timestamps = true;
  swslam::io::carmen2rawlog(opts, [](const std::string&) {});
  const auto gt = swslam::common::readTum(opts.ground_truth);
  ASSERT_EQ(gt.size(), 5u);
  // Each scan with a reference pose comes right after an odometry reading of that pose at
  // its own time; the log's ODOM lines are gone, and RAWLASER (no pose) gets none.
  swslam::io::RawlogReader reader(opts.output);
  swslam::io::RawlogItem item;
  std::shared_ptr<mrpt::obs::CObservationOdometry> pending;
  size_t posed = 0, scans = 0;
  while (reader.next(item))
  {
    if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(item.observation))
    {
      EXPECT_FALSE(pending) << "two odometry readings in a row";
      EXPECT_EQ(odo->sensorLabel, "REFERENCE_ODOMETRY");
      pending = odo;
      continue;
    }
    ASSERT_TRUE(std::dynamic_pointer_cast<CObservation2DRangeScan>(item.observation));
    scans++;
    if (!pending) continue;
    ASSERT_LT(posed, gt.size());
    EXPECT_EQ(pending->timestamp, item.observation->timestamp);
    EXPECT_NEAR((pending->odometry - gt[posed].pose).norm(), 0, 1e-9);
    EXPECT_NEAR(pending->odometry.phi(), gt[posed].pose.phi(), 1e-9);
    posed++;
    pending.reset();
  }
  EXPECT_EQ(posed, gt.size());
  EXPECT_EQ(scans, gt.size() + 1);  // and the RAWLASER scan

  // Read as a run reads it: each FLASER scan's odometry increment is the reference motion.
  swslam::io::ScanSourceOptions so;
  so.sensor_label = "FLASER";
  const auto source = swslam::io::openScanSource(opts.output, so, swslam::io::CarmenParams());
  swslam::sensor::ScanInput in;
  std::vector<std::optional<mrpt::poses::CPose2D>> increments;
  while (source->next(in)) increments.push_back(in.odometry_increment);
  ASSERT_EQ(increments.size(), 3u);  // FLASER at x = 1, 1.5, 2 (see excerpt())
  for (size_t k = 1; k < 3; k++)
  {
    ASSERT_TRUE(increments[k]);
    const auto want = gt[k].pose - gt[k - 1].pose;
    EXPECT_NEAR((*increments[k] - want).norm(), 0, 1e-9) << k;
    EXPECT_NEAR(mrpt::math::wrapToPi(increments[k]->phi() - want.phi()), 0, 1e-9) << k;
  }
}

TEST(CarmenLog, NonNumericUsedParamIsMalformed)
{
  const auto dir = swslam::test::tempDir("carmen_badparam");
  const auto text = "PARAM robot_front_laser_max far nohost 0\n"
                    "PARAM robot_use_laser on nohost 0\n" +
                    laserLine("FLASER", ranges180({}), "0 0 0", "1") + "\n";
  const auto c = convert(writeLog(dir, text), swslam::io::CarmenParams());
  EXPECT_EQ(c.stats.malformed, 1u);
  EXPECT_EQ(c.stats.first_malformed_line, 1u);
  EXPECT_EQ(c.stats.params, 1u);
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("robot_front_laser_max"), std::string::npos) << c.warnings[0];
  EXPECT_EQ(scansOf(c).size(), 1u);
}

TEST(CarmenLog, BadInputGivesClearErrors)
{
  const auto dir = swslam::test::tempDir("carmen_bad");
  EXPECT_THROW(swslam::io::CarmenLogReader(dir + "/missing.log", swslam::io::CarmenParams()),
               std::runtime_error);
  swslam::io::Carmen2RawlogOptions opts;
  opts.input = dir + "/nolaser.log";
  std::ofstream(opts.input) << "NEFF 1\nODOM 0 0 0 0 0 0 1 h 1\n\x01\x02 garbage\n";
  opts.output = dir + "/out.rawlog";
  try
  {
    swslam::io::carmen2rawlog(opts, [](const std::string&) {});
    FAIL() << "no exception";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("no laser scan"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(opts.output));
}

TEST(CarmenLog, ALogInUtf16IsRefusedNamingItsEncoding)
{
  // It read no line ("no laser scan ... 0 odometry readings"), and swslam-carmen2rawlog said
  // "cannot write 'out.rawlog'".
  const auto dir = swslam::test::tempDir("carmen_utf16");
  const std::string text = excerpt();
  for (const bool bom : {true, false})
  {
    std::string wide = bom ? std::string("\xFF\xFE", 2) : "";
    for (char c : text) wide += std::string{c, '\0'};
    const std::string path = dir + "/utf16.log";
    std::ofstream(path, std::ios::binary) << wide;
    try
    {
      swslam::io::CarmenLogReader reader(path, swslam::io::CarmenParams(), [](const std::string&) {});
      FAIL() << "a UTF-16 log was read";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_NE(std::string(e.what()).find("carmen: '" + path + "' is UTF-16LE text ("), std::string::npos) << e.what();
    }
    swslam::io::Carmen2RawlogOptions opts;
    opts.input = path;
    opts.output = dir + "/out.rawlog";
    try
    {
      swslam::io::carmen2rawlog(opts, [](const std::string&) {});
      FAIL() << "a UTF-16 log was converted";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_NE(std::string(e.what()).find("UTF-16LE"), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find("cannot write"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(opts.output));
  }
}

TEST(CarmenLog, ALaserMountedBeyondTheBoundByItsParamsIsRefused)
{
  const auto dir = swslam::test::tempDir("carmen_mount");
  for (const std::string value : {"1e30", "1e4", "-60"})
  {
    std::string text = excerpt();
    const std::string param = "PARAM robot_rearlaser_offset 0.3";
    text.replace(text.find(param), param.size(), "PARAM robot_rearlaser_offset " + value);
    const std::string path = writeLog(dir, text);
    try
    {
      convert(path, swslam::io::CarmenParams());
      FAIL() << value << ": converted";
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_NE(std::string(e.what()).find("line 3: PARAM robot_rearlaser_offset " + value +
                                           " puts the rear laser's sensor mounted at ("),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("beyond the 50 m"), std::string::npos) << e.what();
    }
  }
}

TEST(CarmenLog, ARobotLaserLineMountedBeyondTheBoundIsSkippedAndCounted)
{
  std::string text = excerpt();
  // The ROBOTLASER1 line's robot pose moved 100 m from its laser pose.
  const std::string robot = " 3 4 0.5 0 0 0 0 0 10.3 h 10.3";
  ASSERT_NE(text.find(robot), std::string::npos);
  text.replace(text.find(robot), robot.size(), " -97 4 0.5 0 0 0 0 0 10.3 h 10.3");
  const auto dir = swslam::test::tempDir("carmen_robotlaser_mount");
  const Converted c = convert(writeLog(dir, text), swslam::io::CarmenParams());
  EXPECT_EQ(c.stats.malformed, 2u);  // line 8, and this one
  EXPECT_EQ(c.stats.lasers.count("ROBOTLASER1"), 0u);
  bool said = false;
  for (const auto& w : c.warnings) said |= w.find("laser_pose and robot_pose put the sensor mounted at") != std::string::npos;
  EXPECT_TRUE(said);
}

namespace
{
/** A log of `n` FLASER scans 0.1 s apart from `t0`, one ODOM line before each, gzip-compressed
 * (zlib writes it) at `path`. */
void writeGzipLog(const std::string& path, int n, double t0 = 1000)
{
  std::ostringstream text;
  for (int k = 0; k < n; k++)
  {
    const std::string t = std::to_string(t0 + 0.1 * k);
    text << "ODOM " << 0.1 * k << " 0 0 0.1 0 0 " << t << " h " << t << "\n"
         << laserLine("FLASER", ranges180({}), std::to_string(0.1 * k) + " 0 0", t) << "\n";
  }
  mrpt::io::CFileGZOutputStream out(path);
  const std::string s = text.str();
  out.Write(s.data(), s.size());
}

std::string fileBytes(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

/** Converts `input` to `dir`/out.rawlog: the stats, or the exception's message. */
std::pair<swslam::io::CarmenStats, std::string> convertFile(const std::string& input, const std::string& dir)
{
  swslam::io::Carmen2RawlogOptions opts;
  opts.input = input;
  opts.output = dir + "/out.rawlog";
  opts.ground_truth = dir + "/gt.tum";
  try
  {
    return {swslam::io::carmen2rawlog(opts, [](const std::string&) {}), ""};
  }
  catch (const std::exception& e)
  {
    return {{}, e.what()};
  }
}

size_t rawlogScans(const std::string& path)
{
  swslam::io::RawlogReader reader(path);
  swslam::io::RawlogItem item;
  size_t n = 0;
  while (reader.next(item)) n += std::dynamic_pointer_cast<CObservation2DRangeScan>(item.observation) ? 1 : 0;
  return n;
}
}  // namespace

TEST(CarmenLog, ATruncatedGzipLogConvertsTheScansBeforeTheCutAndSaysWhere)
{
  // It converted about half the scans with no word, as if the log ended there.
  const auto dir = swslam::test::tempDir("carmen_gzcut");
  const std::string full = dir + "/full.log.gz", cut = dir + "/cut.log.gz";
  writeGzipLog(full, 240);
  const std::string bytes = fileBytes(full);
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);

  const auto [stats, error] = convertFile(cut, dir);
  ASSERT_EQ(error, "");
  EXPECT_GT(stats.scans(), 60u);
  EXPECT_LT(stats.scans(), 240u);
  EXPECT_NE(stats.damage.find("the gzip stream is cut short after"), std::string::npos) << stats.damage;
  EXPECT_NE(stats.damage.find("'" + cut + "'"), std::string::npos) << stats.damage;
  // An ODOM and a FLASER line per scan: the last line read is the last scan's or the ODOM after it.
  EXPECT_TRUE(stats.damage.find(", after line " + std::to_string(2 * stats.scans())) != std::string::npos ||
              stats.damage.find(", after line " + std::to_string(2 * stats.scans() + 1)) != std::string::npos)
      << stats.damage;
  EXPECT_NE(swslam::io::formatCarmenStats(stats).find("input damaged, converted up to there: "), std::string::npos);
  EXPECT_EQ(rawlogScans(dir + "/out.rawlog"), stats.scans());
  EXPECT_EQ(swslam::common::readTum(dir + "/gt.tum").size(), stats.scans());

  // Read directly (as swslam does), the cut is an error after the scans before it.
  swslam::io::CarmenLogReader reader(cut, swslam::io::CarmenParams(), [](const std::string&) {});
  swslam::io::CarmenRecord rec;
  size_t scans = 0;
  try
  {
    while (reader.next(rec)) scans += std::dynamic_pointer_cast<CObservation2DRangeScan>(rec.observation) ? 1 : 0;
    ADD_FAILURE() << "the cut log ended cleanly";
  }
  catch (const swslam::io::GzipError& e)
  {
    EXPECT_NE(std::string(e.what()).find("cut short"), std::string::npos) << e.what();
  }
  EXPECT_EQ(scans, stats.scans());
}

TEST(CarmenLog, ABitFlippedGzipLogIsANamedErrorNotACrash)
{
  // It ended with "basic_string::_M_replace_aux": MRPT's read returned 2^64-1 bytes.
  const auto dir = swslam::test::tempDir("carmen_gzflip");
  const std::string full = dir + "/full.log.gz", flipped = dir + "/flipped.log.gz";
  writeGzipLog(full, 240);
  std::string bytes = fileBytes(full);
  for (size_t at = bytes.size() / 2; at < bytes.size() / 2 + 8; at++) bytes[at] = static_cast<char>(bytes[at] ^ 0x5A);
  std::ofstream(flipped, std::ios::binary) << bytes;

  const auto [stats, error] = convertFile(flipped, dir);
  ASSERT_EQ(error, "");
  EXPECT_LT(stats.scans(), 240u);
  EXPECT_NE(stats.damage.find("corrupt gzip data after"), std::string::npos) << stats.damage;
  EXPECT_NE(stats.damage.find("(zlib: "), std::string::npos) << stats.damage;
}

TEST(CarmenLog, ALineWithATimestampOutOfRangeIsSkippedAndCounted)
{
  // One stamp of -1e15 shifted every other by 1e15 (beyond MRPT's clock: written as 0).
  const auto dir = swslam::test::tempDir("carmen_stamp_range");
  std::string text;
  for (int k = 0; k < 10; k++)
    text += laserLine("FLASER", ranges180({}), "0 0 0", k == 4 ? "-1e15" : std::to_string(1000 + 0.1 * k)) + "\n";
  text += "ODOM 0 0 0 0 0 0 1e300 h 0\n";
  const auto c = convert(writeLog(dir, text), swslam::io::CarmenParams());
  EXPECT_EQ(c.stats.timestamp_offset, 0);
  EXPECT_EQ(c.stats.timestamps.at("FLASER").out_of_range, 1u);
  EXPECT_EQ(c.stats.timestamps.at("ODOM").out_of_range, 1u);
  const auto scans = scansOf(c);
  ASSERT_EQ(scans.size(), 9u);
  EXPECT_NEAR(toSec(scans[4]->timestamp), 1000.5, 1e-6);
  EXPECT_EQ(c.records.size(), 9u);  // the ODOM line too
  ASSERT_FALSE(c.warnings.empty());
  EXPECT_NE(c.warnings[0].find(":5: FLASER timestamp -1e+15 s is out of range"), std::string::npos) << c.warnings[0];
  const std::string summary = swslam::io::formatCarmenStats(c.stats);
  EXPECT_NE(summary.find("FLASER: 9 stamps, 0 non-increasing, 0 forward jumps, 1 out of range (lines skipped)"),
            std::string::npos)
      << summary;
}

TEST(CarmenLog, ALogInMicrosecondsIsRefusedSayingSo)
{
  const auto dir = swslam::test::tempDir("carmen_stamp_us");
  std::string text;
  for (int k = 0; k < 10; k++)
    text += laserLine("FLASER", ranges180({}), "0 0 0", std::to_string(1700000000000000LL + 100000LL * k)) + "\n";
  const auto path = writeLog(dir, text);
  try
  {
    swslam::io::CarmenLogReader reader(path, swslam::io::CarmenParams(), [](const std::string&) {});
    ADD_FAILURE() << "a log in microseconds was accepted";
  }
  catch (const std::runtime_error& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("10 of 10 timestamps are out of range"), std::string::npos) << what;
    EXPECT_NE(what.find("(microseconds rather than seconds?)"), std::string::npos) << what;
    EXPECT_NE(what.find("not converted"), std::string::npos) << what;
  }
}

namespace
{
/** A raw log: FLASER lines whose odometry fields (a pose drifting from the reference) differ
 * from their x y theta, one repeated timestamp, and no ODOM line. */
std::string rawLog()
{
  std::ostringstream s;
  s << "PARAM robot_frontlaser_offset 0.1 nohost 0\n";
  for (int k = 0; k < 4; k++)
  {
    const double t = k == 2 ? 20.1 : 20 + 0.1 * k;  // scan 2 repeats scan 1's time
    std::ostringstream l;
    l << "FLASER 180";
    for (int i = 0; i < 180; i++) l << " " << 2 + 0.01 * i;
    l << " " << 0.5 * k << " 0 0 " << 0.55 * k << " " << 0.01 * k << " " << 0.02 * k << " " << t << " h " << t;
    s << l.str() << "\n";
  }
  return s.str();
}
}  // namespace

TEST(CarmenLog, ALogWithoutOdomLinesHasItsOdometryInTheLaserLines)
{
  const auto dir = swslam::test::tempDir("carmen_raw_odometry");
  swslam::io::CarmenParams params;
  params.repair_timestamps = true;
  const auto c = convert(writeLog(dir, rawLog()), params);
  EXPECT_EQ(c.stats.odometry_source, swslam::io::CarmenOdometrySource::LaserFields);
  EXPECT_EQ(c.stats.odometry, 4u);
  ASSERT_EQ(c.records.size(), 8u);
  // Each scan right after its line's odometry, at the scan's written (repaired) time.
  for (int k = 0; k < 4; k++)
  {
    SCOPED_TRACE(k);
    const auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(c.records[2 * k].observation);
    const auto scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(c.records[2 * k + 1].observation);
    ASSERT_TRUE(odo && scan);
    EXPECT_EQ(odo->sensorLabel, "ODOM");
    EXPECT_EQ(odo->timestamp, scan->timestamp);
    EXPECT_EQ(c.records[2 * k].line, c.records[2 * k + 1].line);
    EXPECT_FALSE(c.records[2 * k].reference_pose);
    EXPECT_NEAR(odo->odometry.x(), 0.55 * k, 1e-12);
    EXPECT_NEAR(odo->odometry.y(), 0.01 * k, 1e-12);
    EXPECT_NEAR(odo->odometry.phi(), 0.02 * k, 1e-12);
    EXPECT_NEAR(c.records[2 * k + 1].reference_pose->x(), 0.5 * k, 1e-12);  // x y theta stays the reference
  }
  EXPECT_GT(toSec(c.records[4].observation->timestamp), toSec(c.records[2].observation->timestamp) + 0.05);  // repaired
  EXPECT_NE(swslam::io::formatCarmenStats(c.stats).find("odometry: 4 (from the FLASER/RLASER odom_x odom_y "
                                                         "odom_theta fields: the log has no ODOM lines)"),
            std::string::npos);

  // Read as a run reads the log directly: each scan's increment is its odometry's motion.
  swslam::io::ScanSourceOptions so;
  const auto source = swslam::io::openScanSource(dir + "/excerpt.log", so, params);
  EXPECT_NE(source->describe().find("odom_x odom_y odom_theta"), std::string::npos) << source->describe();
  swslam::sensor::ScanInput in;
  for (int k = 0; k < 4; k++)
  {
    ASSERT_TRUE(source->next(in));
    if (k == 0) continue;
    ASSERT_TRUE(in.odometry_increment);
    const mrpt::poses::CPose2D want =
        mrpt::poses::CPose2D(0.55 * k, 0.01 * k, 0.02 * k) - mrpt::poses::CPose2D(0.55 * (k - 1), 0.01 * (k - 1), 0.02 * (k - 1));
    EXPECT_NEAR((*in.odometry_increment - want).norm(), 0, 1e-9) << k;
    EXPECT_NEAR(in.odometry_increment->phi(), 0.02, 1e-9) << k;
  }

  params.laser_only = true;
  const auto laser_only = convert(writeLog(dir, rawLog()), params);
  EXPECT_EQ(laser_only.records.size(), 4u);
  EXPECT_EQ(laser_only.stats.odometry, 0u);
  EXPECT_EQ(laser_only.stats.odometry_dropped, 4u);
  EXPECT_NE(swslam::io::formatCarmenStats(laser_only.stats).find("odometry: 0 (4 laser-line odometry readings dropped"),
            std::string::npos);
}

TEST(CarmenLog, ALogWithOdomLinesKeepsThemAndIgnoresTheLaserLinesOdometry)
{
  // The corrected logs: ODOM lines, and odometry fields that repeat the reference pose.
  const auto dir = swslam::test::tempDir("carmen_odom_lines");
  const auto c = convert(writeLog(dir, excerpt()), swslam::io::CarmenParams());
  EXPECT_EQ(c.stats.odometry_source, swslam::io::CarmenOdometrySource::OdomLines);
  EXPECT_EQ(c.stats.odometry, 2u);
  size_t odometry = 0;
  for (const auto& r : c.records)
    if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(r.observation))
    {
      odometry++;
      EXPECT_NEAR(odo->velocityLocal.vx, 0.1, 1e-12);  // an ODOM line's
    }
  EXPECT_EQ(odometry, 2u);

  std::ofstream(dir + "/none.log") << "RAWLASER1 0 -1.5 3 0.5 30 0.01 0 7 1 2 3 4 5 6 7 0 10.4 h 10.4\n";
  const auto none = convert(dir + "/none.log", swslam::io::CarmenParams());
  EXPECT_EQ(none.stats.odometry_source, swslam::io::CarmenOdometrySource::None);
  EXPECT_NE(swslam::io::formatCarmenStats(none.stats).find("odometry: 0 (the log has none)"), std::string::npos);
}

// Parsing of single CARMEN lines, and the saturation and timestamp rules.
#include <swslam/io/carmen_line.h>
#include <swslam/common/param_table.h>
#include <swslam/io/carmen_log.h>
#include <swslam/io/carmen_rules.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using swslam::io::CarmenLine;
using swslam::io::parseCarmenLine;

TEST(CarmenLine, ParsesFlaserFields)
{
  const auto l = parseCarmenLine("FLASER 3 1.5 81.91 nan 1 2 0.5 1.1 2.1 0.6 12.25 pippo 12.3");
  ASSERT_EQ(l.kind, CarmenLine::Kind::Laser);
  EXPECT_EQ(l.laser.label, "FLASER");
  ASSERT_EQ(l.laser.ranges.size(), 3u);
  EXPECT_FLOAT_EQ(l.laser.ranges[0], 1.5f);
  EXPECT_FLOAT_EQ(l.laser.ranges[1], 81.91f);
  EXPECT_TRUE(std::isnan(l.laser.ranges[2]));
  EXPECT_FALSE(l.laser.has_geometry);
  ASSERT_TRUE(l.laser.has_pose);
  EXPECT_DOUBLE_EQ(l.laser.robot_pose.x, 1);  // x y theta, not the odometry fields
  EXPECT_DOUBLE_EQ(l.laser.robot_pose.phi, 0.5);
  ASSERT_TRUE(l.laser.has_odometry);
  EXPECT_DOUBLE_EQ(l.laser.odometry_pose.x, 1.1);
  EXPECT_DOUBLE_EQ(l.laser.odometry_pose.y, 2.1);
  EXPECT_DOUBLE_EQ(l.laser.odometry_pose.phi, 0.6);
  EXPECT_DOUBLE_EQ(l.laser.timestamp, 12.25);  // ipc_timestamp, not the logger's
}

TEST(CarmenLine, ParsesRobotLaserAndRawLaser)
{
  const auto r = parseCarmenLine(
      "ROBOTLASER1 0 -1.5 3 1.5 50 0.01 0 3 1 2 3 2 0.5 0.5 "
      "1.2 2 0.3 1 2 0.3 0.1 0.2 0 0 0 13.5 host 13.6");
  ASSERT_EQ(r.kind, CarmenLine::Kind::Laser);
  EXPECT_TRUE(r.laser.has_geometry && r.laser.has_pose && r.laser.has_laser_pose);
  EXPECT_FALSE(r.laser.has_odometry);  // a single robot pose: the reference
  EXPECT_DOUBLE_EQ(r.laser.start_angle, -1.5);
  EXPECT_DOUBLE_EQ(r.laser.fov, 3);
  EXPECT_DOUBLE_EQ(r.laser.resolution, 1.5);
  EXPECT_DOUBLE_EQ(r.laser.max_range, 50);
  EXPECT_EQ(r.laser.ranges.size(), 3u);
  EXPECT_DOUBLE_EQ(r.laser.laser_pose.x, 1.2);
  EXPECT_DOUBLE_EQ(r.laser.robot_pose.x, 1);
  EXPECT_DOUBLE_EQ(r.laser.timestamp, 13.5);

  const auto w = parseCarmenLine("RAWLASER3 2 -2 4 0.01 5.6 0.01 0 2 1 2 0 7.5 host 7.5");
  ASSERT_EQ(w.kind, CarmenLine::Kind::Laser);
  EXPECT_FALSE(w.laser.has_pose);
  EXPECT_EQ(swslam::io::carmenSensorOf(w.laser.label), "laser3");
  EXPECT_DOUBLE_EQ(w.laser.timestamp, 7.5);
}

TEST(CarmenLine, ParsesOdomParamCommentsAndUnknown)
{
  const auto o = parseCarmenLine("ODOM 1 2 0.5 0.3 0.1 0 42.5 host 42.5");
  ASSERT_EQ(o.kind, CarmenLine::Kind::Odometry);
  EXPECT_DOUBLE_EQ(o.odometry.pose.y, 2);
  EXPECT_DOUBLE_EQ(o.odometry.tv, 0.3);
  EXPECT_DOUBLE_EQ(o.odometry.timestamp, 42.5);
  const auto p = parseCarmenLine("PARAM robot_frontlaser_offset 0.25 nohost 0");
  ASSERT_EQ(p.kind, CarmenLine::Kind::Param);
  EXPECT_EQ(p.param_name, "robot_frontlaser_offset");
  EXPECT_EQ(p.param_value, "0.25");
  EXPECT_EQ(parseCarmenLine("# message formats").kind, CarmenLine::Kind::Blank);
  EXPECT_EQ(parseCarmenLine("   \r").kind, CarmenLine::Kind::Blank);
  const auto u = parseCarmenLine("NEFF 59.6");
  EXPECT_EQ(u.kind, CarmenLine::Kind::Unknown);
  EXPECT_EQ(u.message, "NEFF");
}

TEST(CarmenLine, MalformedLinesNameTheProblem)
{
  const std::pair<const char*, const char*> cases[] = {
      {"FLASER 5 1 2 3", "only"},                                 // fewer ranges than n
      {"FLASER 2 1 2 0 0 0 0 0 0", "ipc_timestamp"},              // truncated
      {"FLASER 2 1 x 0 0 0 0 0 0 1 h 1", "not a number"},          // bad range
      {"FLASER -2 1 2 0 0 0 0 0 0 1 h 1", "num_readings"},         // negative count
      {"FLASER 999999999 1", "num_readings"},                      // absurd count
      {"FLASER 2 1 2 0 0 0 0 0 0 1 h 1 extra", "unexpected"},      // extra fields
      {"ODOM 1 2 nan 0 0 0 1 h 1", "not finite"},                  // non-finite pose
      {"ODOM 1 -3e9 0 0 0 0 1 h 1", "position beyond"},           // no trajectory's position
      {"FLASER 1 1 2.5e73 0 0 0 0 0 1 h 1", "position beyond"},   // truth pose of the fuzz crash
      {"ODOM 1 2 0 0 0 0 inf h 1", "ipc_timestamp"},               // non-finite timestamp
      // a laser 100 m from its robot: no mounting (sensor/input_bounds.h)
      {"ROBOTLASER1 0 -1.2 2 0.02 20 0.01 0 2 4 4 0 103 4 0 3 4 0 0 0 0 0 0 10.3 h 10.3",
       "laser_pose and robot_pose put the sensor mounted at (100, 0, 0) m, 100 m from the vehicle: beyond the 50 m"},
      {"PARAM lonely", "param_value"}};
  for (const auto& [text, expected] : cases)
  {
    try
    {
      parseCarmenLine(text);
      ADD_FAILURE() << "accepted: " << text;
    }
    catch (const swslam::io::CarmenLineError& e)
    {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
          << text << " -> " << e.what();
    }
  }
}

namespace
{
/** Slow, obvious saturation rule: sort everything, take the cluster below the maximum. */
std::optional<double> slowSaturation(std::vector<double> r, double tol, size_t min_count)
{
  const auto bad = [](double v) { return !(v > 0) || !std::isfinite(v); };
  r.erase(std::remove_if(r.begin(), r.end(), bad), r.end());
  if (r.empty()) return std::nullopt;
  std::sort(r.begin(), r.end());
  const double low = r.back() * (1 - tol);
  const auto first = std::lower_bound(r.begin(), r.end(), low);
  if (static_cast<size_t>(r.end() - first) < min_count) return std::nullopt;
  return *first;
}
}  // namespace

TEST(CarmenRules, SaturationMatchesSlowVersion)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 30.0);
  for (int trial = 0; trial < 50; trial++)
  {
    std::vector<double> r;
    const int saturated = trial % 10;  // 0..9 readings at the maximum
    const double top = 32.767 + 0.01 * trial;
    for (int i = 0; i < 2000; i++)
    {
      r.push_back(u(rng));
      if (i % 200 == 0 && i / 200 < saturated) r.push_back(top - 0.004 * (i / 200));
    }
    r.push_back(-1.0);
    r.push_back(std::numeric_limits<double>::quiet_NaN());
    std::shuffle(r.begin(), r.end(), rng);
    swslam::io::SaturationDetector d(0.005, 5);
    for (double v : r) d.add(v);
    const auto expected = slowSaturation(r, 0.005, 5);
    ASSERT_EQ(d.threshold().has_value(), expected.has_value()) << "trial " << trial;
    if (expected) EXPECT_DOUBLE_EQ(*d.threshold(), *expected);
    if (saturated >= 5) EXPECT_GE(*d.threshold(), top - 0.004 * (saturated - 1) - 1e-12);
  }
}

TEST(CarmenRules, NoSaturationWithoutACluster)
{
  swslam::io::SaturationDetector d(0.005, 5);
  for (double r : {1.0, 5.0, 12.0, 30.0, 29.0, 30.0}) d.add(r);  // only 2 at the top
  EXPECT_FALSE(d.threshold().has_value());
  EXPECT_DOUBLE_EQ(d.largest(), 30.0);
  for (int i = 0; i < 3; i++) d.add(29.9);  // 5 readings within 0.5 %: saturation at 29.9
  ASSERT_TRUE(d.threshold().has_value());
  EXPECT_DOUBLE_EQ(*d.threshold(), 29.9);
}

TEST(CarmenRules, AGlitchAboveThePileDoesNotHideTheSaturation)
{
  // 969 "no return" rays at 81.91 m among 40000 readings up to 60 m, and one reading of 500 m:
  // the maximum range stays 81.91 m, the glitch is counted.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.5, 60.0);
  swslam::io::SaturationDetector d(0.005, 5);
  for (int i = 0; i < 40000; i++) d.add(u(rng));
  for (int i = 0; i < 969; i++) d.add(81.91);
  d.add(500.0);
  ASSERT_TRUE(d.threshold().has_value());
  EXPECT_DOUBLE_EQ(*d.threshold(), 81.91);
  EXPECT_EQ(d.glitchesAbove(), 1u);
  EXPECT_DOUBLE_EQ(d.largest(), 500.0);

  // The smooth tail of a log with no saturation is no pile, glitch or not.
  swslam::io::SaturationDetector tail(0.005, 5);
  for (int i = 0; i < 40000; i++) tail.add(u(rng));
  tail.add(500.0);
  EXPECT_FALSE(tail.threshold().has_value());
  EXPECT_EQ(tail.glitchesAbove(), 0u);

  // As many readings above the pile as make a pile themselves: no glitches, the old rule.
  swslam::io::SaturationDetector many(0.005, 5);
  for (int i = 0; i < 969; i++) many.add(81.91);
  for (int i = 0; i < 6; i++) many.add(500.0);
  ASSERT_TRUE(many.threshold().has_value());
  EXPECT_DOUBLE_EQ(*many.threshold(), 500.0);
}

TEST(CarmenRules, TimestampsDetectedAndRepaired)
{
  const std::vector<double> raw = {0, 0, 0.2, 0.2, 0.1, 0.4, 4.3e9, 4.3e9};
  for (bool repair : {false, true})
  {
    swslam::io::TimestampSequence seq(0.1, 3600, repair);
    std::vector<double> out;
    size_t non_increasing = 0, jumps = 0;
    for (double t : raw)
    {
      swslam::io::TimestampIssue issue;
      out.push_back(seq.next(t, issue));
      non_increasing += issue == swslam::io::TimestampIssue::NonIncreasing;
      jumps += issue == swslam::io::TimestampIssue::ForwardJump;
    }
    if (!repair)
    {
      EXPECT_EQ(out, raw);
      EXPECT_EQ(non_increasing, 4u);  // 0, 0.2, 0.1, 4.3e9 repeated
      EXPECT_EQ(jumps, 1u);
      continue;
    }
    // Repaired: 0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7 (each bad one is previous + 0.1).
    for (size_t i = 0; i < out.size(); i++) EXPECT_NEAR(out[i], 0.1 * i, 1e-12) << i;
    EXPECT_EQ(non_increasing, 4u);
    EXPECT_EQ(jumps, 2u);
  }
}

TEST(CarmenRules, MedianPeriodIgnoresBadSteps)
{
  EXPECT_DOUBLE_EQ(swslam::io::medianPositivePeriod({0, 0.1, 0.2, 0.2, 0.1, 0.35, 4.3e9}, 3600, 9),
                   0.1);
  EXPECT_DOUBLE_EQ(swslam::io::medianPositivePeriod({0, 0, 0}, 3600, 0.1), 0.1);
  EXPECT_DOUBLE_EQ(swslam::io::medianPositivePeriod({}, 3600, 0.1), 0.1);
}

TEST(CarmenParams, LoadStrictlyAndCheckRanges)
{
  mrpt::config::CConfigFileMemory cfg;
  cfg.write("carmen", "max_range", 40.0);
  cfg.write("carmen", "repair_timestamps", true);
  const auto p = swslam::io::CarmenParams::table().load(cfg);
  EXPECT_DOUBLE_EQ(p.max_range, 40.0);
  EXPECT_TRUE(p.repair_timestamps);
  EXPECT_NO_THROW(p.check());
  cfg.write("carmen", "max_rnage", 1.0);
  EXPECT_THROW(swslam::io::CarmenParams::table().load(cfg), std::invalid_argument);
  swslam::io::CarmenParams bad;
  bad.default_period = 0;
  try
  {
    bad.check();
    FAIL();
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("default_period"), std::string::npos);
  }
}

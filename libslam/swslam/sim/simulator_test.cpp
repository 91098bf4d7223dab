// A whole simulator run on a small scenario: reproducible bytes, a rawlog that reads
// back with swslam's reader, returns that lie on the world's shapes, and ground truth
// files that match the path.
#include "sim_test_scenario.h"
#include "test_support.h"

#include <swslam/common/tum_io.h>
#include <swslam/io/rawlog_reader.h>
#include <swslam/sensor/scan.h>
#include <swslam/sim/simulator.h>
#include <swslam/sim/terrain.h>
#include <swslam/sim/vehicle.h>

#include <mrpt/obs/CObservationOdometry.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

using namespace swslam::sim;

namespace
{
std::string readBytes(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

/** Distance from `p` to the surface of the nearest shape. */
double distanceToWorld(const World& w, const Eigen::Vector2d& p)
{
  double best = 1e9;
  for (const auto& s : w.shapes)
  {
    double d;
    if (s.isCircle())
      d = std::abs((p - s.a).norm() - s.radius);
    else
    {
      const Eigen::Vector2d e = s.b - s.a;
      const double u = std::clamp((p - s.a).dot(e) / e.squaredNorm(), 0.0, 1.0);
      d = (p - (s.a + u * e)).norm();
    }
    best = std::min(best, d);
  }
  return best;
}

SimulationSummary runInto(const Scenario& sc, const std::string& name)
{
  return runSimulation(sc, swslam::test::tempDir(name));
}
}  // namespace

TEST(SimSimulator, SameSeedSameBytesOtherSeedOtherBytes)
{
  const auto a = runInto(swslam::test::smallScenario(3), "sim_run_a");
  const auto b = runInto(swslam::test::smallScenario(3), "sim_run_b");
  const auto c = runInto(swslam::test::smallScenario(4), "sim_run_c");
  ASSERT_EQ(a.files.size(), 4u);
  for (size_t i = 0; i < a.files.size(); i++)
  {
    SCOPED_TRACE(a.files[i].first);
    EXPECT_EQ(readBytes(a.files[i].first), readBytes(b.files[i].first));
  }
  EXPECT_GT(a.files[0].second, 10000u);
  EXPECT_NE(readBytes(a.files[0].first), readBytes(c.files[0].first));
}

TEST(SimSimulator, RawlogReadsBackOnTheWorldAndMatchesGroundTruth)
{
  const Scenario sc = swslam::test::smallScenario();
  const auto sum = runInto(sc, "sim_run_readback");
  const std::string base = sum.files[0].first.substr(0, sum.files[0].first.size() - 7);
  const VehiclePath path(sc.vehicle.waypoints, sc.vehicle.closed, sc.vehicle.speed);
  const World world = generateWorld(sc, path);
  const auto truth = swslam::common::readTum(base + ".gt.tum");
  ASSERT_EQ(truth.size(), sum.scans);

  swslam::io::RawlogReader reader(base + ".rawlog");
  swslam::io::RawlogItem item;
  size_t scans = 0, odometry = 0, valid = 0, invalid = 0;
  double t0 = 0;
  while (reader.next(item))
  {
    ASSERT_TRUE(item.observation);
    const double t = mrpt::Clock::toDouble(item.observation->timestamp);
    if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(item.observation))
    {
      EXPECT_EQ(odo->sensorLabel, "ODOMETRY");
      odometry++;
      continue;
    }
    auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(item.observation);
    ASSERT_TRUE(obs);
    if (scans == 0) t0 = t;
    EXPECT_NEAR(t - t0, scans / sc.sensor.rate, 1e-6);
    EXPECT_NEAR(t, truth[scans].t, 1e-6);
    EXPECT_EQ(obs->sensorLabel, sc.sensor.label);
    EXPECT_FLOAT_EQ(obs->maxRange, sc.sensor.max_range);
    const swslam::sensor::Scan s = swslam::sensor::scanFromObservation(*obs);
    ASSERT_EQ(s.beam_count, sc.sensor.rays());
    EXPECT_NEAR(s.aperture, sc.sensor.fov, 1e-6);
    for (size_t i = 0; i < obs->getScanSize(); i++)
      if (!obs->getScanRangeValidity(i)) EXPECT_FLOAT_EQ(obs->getScanRange(i), obs->maxRange);
    // Every return lies on a shape, within the range noise.
    const mrpt::poses::CPose2D sensor = truth[scans].pose + s.sensor_pose;
    for (const auto& p : s.points)
    {
      const mrpt::poses::CPose2D q = sensor + mrpt::poses::CPose2D(p.x(), p.y(), 0);
      ASSERT_LT(distanceToWorld(world, {q.x(), q.y()}), 5 * sc.sensor.range_noise_std + 1e-4);
    }
    valid += s.size();
    invalid += s.rejected.total();
    scans++;
  }
  EXPECT_EQ(scans, sum.scans);
  EXPECT_EQ(odometry, sum.scans);
  EXPECT_GT(valid, 20 * scans);
  EXPECT_GT(invalid, 5 * scans);  // open water and dropouts

  // Ground truth on the path, and the same in MRPT's "t x y phi" text.
  std::ifstream mrpt_gt(base + ".gt.txt");
  std::string line;
  size_t k = 0;
  while (std::getline(mrpt_gt, line))
  {
    std::istringstream ss(line);
    double t, x, y, phi;
    std::string rest;
    ASSERT_TRUE(ss >> t >> x >> y >> phi) << line;
    EXPECT_FALSE(ss >> rest) << line;
    ASSERT_LT(k, truth.size());
    const auto expected = path.poseAt(k / sc.sensor.rate);
    EXPECT_NEAR(truth[k].pose.x(), expected.x(), 1e-6);
    EXPECT_NEAR(truth[k].pose.phi(), expected.phi(), 1e-6);
    EXPECT_NEAR(x, expected.x(), 1e-5);
    EXPECT_NEAR(y, expected.y(), 1e-5);
    EXPECT_NEAR(t, truth[k].t, 1e-5);
    k++;
  }
  EXPECT_EQ(k, truth.size());
}

TEST(SimSimulator, NoOdometryWhenDisabledAndValidityFiguresAreFractions)
{
  Scenario sc = swslam::test::smallScenario();
  sc.odometry.enabled = false;
  const auto sum = runInto(sc, "sim_run_noodo");
  swslam::io::RawlogReader reader(sum.files[0].first);
  swslam::io::RawlogItem item;
  size_t n = 0;
  while (reader.next(item))
  {
    ASSERT_TRUE(std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(item.observation));
    n++;
  }
  EXPECT_EQ(n, sum.scans);
  EXPECT_GT(sum.valid_min, 0.0);
  EXPECT_LE(sum.valid_min, sum.valid_median);
  EXPECT_LT(sum.valid_median, 1.0);
}

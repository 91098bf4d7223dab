// The simulator-backed scan source of the SCIP emulator: the simulator's own scans, in mm,
// along the ground-truth path; a scenario whose sensor is not the emulated one is refused.
#include "scip/scip_sim_source.h"
#include "sim_test_scenario.h"

#include <swslam/sim/grid.h>
#include <swslam/sim/sensor.h>
#include <swslam/sim/terrain.h>
#include <swslam/sim/vehicle.h>

#include <gtest/gtest.h>

namespace swslam::scip
{
namespace
{
sim::Scenario utmScenario()
{
  sim::Scenario sc = test::smallScenario();
  sc.sensor.resolution = 0.25 * M_PI / 180;
  sc.sensor.rate = 40;
  return sc;
}

TEST(ScipSimSource, GivesTheSimulatorsScansInMillimetres)
{
  const sim::Scenario sc = utmScenario();
  const SimScanSource source(sc);
  EXPECT_DOUBLE_EQ(source.rate(), 40.0);
  // The same simulator, run directly: same world, same first draws.
  const sim::VehiclePath path(sc.vehicle.waypoints, sc.vehicle.closed, sc.vehicle.speed);
  const sim::World world = sim::generateWorld(sc, path);
  const sim::ShapeGrid grid(world, sc.world.grid_cell);
  sim::LidarSimulator lidar(sc.sensor, grid, sc.world.seed);
  EXPECT_EQ(source.pathScans(), static_cast<uint64_t>(std::floor(path.duration() * 40)) + 1);

  for (uint64_t k : {0u, 1u, 7u})
  {
    const Scan scan = source(k);
    const auto pose = path.poseAt(k / 40.0);
    EXPECT_NEAR(source.pose(k).distanceTo(pose), 0.0, 1e-12);
    const auto obs = lidar.scan(pose, mrpt::Clock::fromDouble(sc.vehicle.start_time + k / 40.0), k);
    ASSERT_EQ(scan.ranges_mm.size(), 1081u);
    ASSERT_EQ(obs->getScanSize(), 1081u);
    size_t valid = 0;
    for (size_t i = 0; i < 1081; i++)
    {
      if (obs->getScanRangeValidity(i))
      {
        valid++;
        EXPECT_NEAR(scan.ranges_mm[i], obs->getScanRange(i) * 1000.0, 0.5) << i;
        EXPECT_GE(scan.ranges_mm[i], 20u);
      }
      else
        EXPECT_EQ(scan.ranges_mm[i], kNoEcho);
    }
    EXPECT_GT(valid, 100u);
  }
}

TEST(ScipSimSource, RefusesAScenarioWhoseSensorIsNotTheEmulatedOne)
{
  sim::Scenario sc = utmScenario();
  sc.sensor.resolution = 0.5 * M_PI / 180;
  try
  {
    SimScanSource bad(sc);
    FAIL() << "a 0.5 deg sensor was accepted for a UTM-30LX";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("resolution_DEG = 0.5"), std::string::npos) << e.what();
  }
  sc = utmScenario();
  sc.sensor.rate = 10;
  EXPECT_THROW(SimScanSource{sc}, std::invalid_argument);
  SensorInfo urg04;  // a URG-04LX: 683 steps of 360/1024 deg at 10 Hz
  urg04.ares = 1024;
  urg04.amin = 44;
  urg04.amax = 725;
  urg04.afrt = 384;
  urg04.scan_rpm = 600;
  EXPECT_THROW(SimScanSource(utmScenario(), urg04), std::invalid_argument);
}

}  // namespace
}  // namespace swslam::scip

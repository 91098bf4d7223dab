// Scenario files: every shipped one loads and fits its world; bad keys and values are
// rejected with a message naming the key, before any output is written.
#include "sim_test_scenario.h"
#include "test_support.h"

#include <swslam/sim/simulator.h>
#include <swslam/sim/terrain.h>
#include <swslam/sim/vehicle.h>
#include <swslam/sim/world.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

namespace fs = std::filesystem;
using namespace swslam::sim;

namespace
{
/** Writes the small scenario with one line replaced (regex on the whole text) and
 * returns the error of loading and running it, or "" if it ran. */
std::string errorOf(const std::string& pattern, const std::string& replacement,
                    const std::string& out_dir)
{
  const std::string dir = swslam::test::tempDir("sim_scenario_bad");
  const std::string text = std::regex_replace(formatScenario(swslam::test::smallScenario()),
                                              std::regex(pattern), replacement);
  const std::string file = dir + "/bad.ini";
  swslam::test::writeText(file, text);
  try
  {
    runSimulation(loadScenario(file), out_dir);
  }
  catch (const std::invalid_argument& e)
  {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(SimScenario, RoundTripThroughIniText)
{
  const Scenario a = swslam::test::smallScenario();
  const std::string file = swslam::test::tempDir("sim_scenario_rt") + "/round-trip.ini";
  swslam::test::writeText(file, formatScenario(a));
  const Scenario b = loadScenario(file);
  EXPECT_EQ(b.name, "round-trip");
  EXPECT_EQ(b.world.seed, a.world.seed);
  EXPECT_DOUBLE_EQ(b.sensor.fov, a.sensor.fov);
  EXPECT_DOUBLE_EQ(b.sensor.resolution, a.sensor.resolution);
  EXPECT_EQ(b.sensor.rays(), 181u);
  EXPECT_DOUBLE_EQ(b.vehicle.start_time, a.vehicle.start_time);
  EXPECT_DOUBLE_EQ(b.vehicle.max_turn_rate, a.vehicle.max_turn_rate);
  ASSERT_EQ(b.vehicle.waypoints.size(), a.vehicle.waypoints.size());
  EXPECT_EQ(b.vehicle.waypoints[1], a.vehicle.waypoints[1]);
  EXPECT_DOUBLE_EQ(b.vegetation.reed_density, a.vegetation.reed_density);
  EXPECT_EQ(formatScenario(b), formatScenario(a));
}

TEST(SimScenario, WallsRoundTripAndStopRays)
{
  Scenario a = swslam::test::smallScenario();
  a.building.walls = {{{-10, 5}, {10, 5}}, {{-3.5, -20}, {-3.5, -15.25}}};
  const std::string file = swslam::test::tempDir("sim_scenario_walls") + "/walls.ini";
  swslam::test::writeText(file, formatScenario(a));
  const Scenario b = loadScenario(file);
  ASSERT_EQ(b.building.walls.size(), 2u);
  EXPECT_EQ(b.building.walls[1].second, Eigen::Vector2d(-3.5, -15.25));
  EXPECT_EQ(formatScenario(b), formatScenario(a));
  // A ray from the path straight up (+y) stops on the first wall, from either side.
  const VehiclePath path(b.vehicle.waypoints, b.vehicle.closed, b.vehicle.speed);
  const World world = generateWorld(b, path);
  Ray up;
  up.origin = Eigen::Vector2d(0, -6);
  up.dir = Eigen::Vector2d(0, 1);
  EXPECT_NEAR(castBruteForce(world, up, 100), 11.0, 1e-9);
  Ray down;
  down.origin = Eigen::Vector2d(0, 8);
  down.dir = Eigen::Vector2d(0, -1);
  EXPECT_NEAR(castBruteForce(world, down, 100), 3.0, 1e-9);
}

TEST(SimScenario, EveryShippedScenarioLoadsAndFitsItsWorld)
{
  size_t n = 0;
  for (const auto& e : fs::directory_iterator(SWSLAM_SOURCE_DIR "/datasets/scenarios"))
  {
    if (e.path().extension() != ".ini") continue;
    SCOPED_TRACE(e.path().string());
    const Scenario sc = loadScenario(e.path().string());
    const VehiclePath path(sc.vehicle.waypoints, sc.vehicle.closed, sc.vehicle.speed);
    EXPECT_NO_THROW(checkPathFits(sc, generateWorld(sc, path), path));
    n++;
  }
  EXPECT_GE(n, 4u);
}

TEST(SimScenario, BadKeysAndValuesNameTheKeyAndWriteNothing)
{
  const std::string out = swslam::test::tempDir("sim_scenario_out") + "/out";
  const struct
  {
    std::string pattern, replacement, expected;
  } cases[] = {
      {"rate_hz *= *[^\n]*\n", "", "missing key [sensor] rate_hz"},
      {"range_noise_std", "range_noise_sdt", "range_noise_sdt"},
      {"\\[odometry\\]", "[odometry]\nyaw_bias = 3", "unknown key 'yaw_bias'"},
      {"\\[odometry\\]", "[odometri]", "unknown section [odometri]"},
      {"max_range *= *[^\n]*", "max_range = far", "[sensor] max_range = 'far'"},
      {"max_range *= *[^\n]*", "max_range = 0.1", "[sensor] max_range = 0.1 must be > min_range"},
      {"resolution_DEG *= *[^\n]*", "resolution_DEG = 0.7", "resolution_DEG = 0.7 does not divide"},
      {"dropout_prob *= *[^\n]*", "dropout_prob = 1.5", "[sensor] dropout_prob"},
      {"closed *= *[^\n]*", "closed = maybe", "[vehicle] closed"},
      {"waypoints *= *[^\n]*", "waypoints = 1 2, 3", "[vehicle] waypoints"},
      {"seed *= *[^\n]*", "seed = -4", "[world] seed"},
      {"bank_pass_through *= *[^\n]*", "bank_pass_through = 1.5",
       "[terrain] bank_pass_through must be a probability in [0, 1]"},
      {"bank_pass_through *= *[^\n]*\n", "", "missing key [terrain] bank_pass_through"},
      {"size_x *= *[^\n]*", "size_x = 10", "leaves the world"},
      {"waypoints *= *[^\n]*", "waypoints = -6 -8, 0 0, 6 8, 12 16", "onto land"},
      {"waypoints *= *[^\n]*", "waypoints = -6 -8, 0 -6, -5 -7", "max_turn_rate_DEG"},
      {"\\[odometry\\]", "[building]\nwalls = 1 2 3\n[odometry]", "wall '1 2 3' is not 'x1 y1 x2 y2'"},
      {"\\[odometry\\]", "[building]\nwalls = 1 2 1 2\n[odometry]", "wall '1 2 1 2' has no length"},
      {"\\[odometry\\]", "[building]\nwalls = 0 20 0 40\n[odometry]", "[building] walls end (0, 40) lies outside"},
      {"\\[odometry\\]", "[building]\n[odometry]", "missing key [building] walls"},
      {"\\[odometry\\]", "[building]\nwalls = -2 -6 2 -6\n[odometry]", "within 0.5 m of the wall (-2, -6)-(2, -6)"},
  };
  for (const auto& c : cases)
  {
    SCOPED_TRACE(c.pattern + " -> " + c.replacement);
    const std::string err = errorOf(c.pattern, c.replacement, out);
    EXPECT_NE(err.find(c.expected), std::string::npos) << "error was: " << err;
    EXPECT_FALSE(fs::exists(out)) << "output written despite the error";
  }
  // The unmodified scenario runs and writes its outputs.
  EXPECT_EQ(errorOf("^$", "", out), "");
  EXPECT_TRUE(fs::exists(out + "/bad.rawlog"));
}

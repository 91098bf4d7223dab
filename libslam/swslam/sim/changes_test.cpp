// [changes]: the same world with rocks taken away and put in the band around the path, the
// same each time for a seed; too few rocks to take is a named error; the section goes through
// the scenario's .ini text.
#include "sim_test_scenario.h"

#include <swslam/sim/changes.h>
#include <swslam/sim/terrain.h>
#include <swslam/sim/vehicle.h>

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.h"

using namespace swslam::sim;

namespace
{
/** The valley lake, whose eight rocks lie around its path. */
Scenario valley() { return loadScenario(SWSLAM_SOURCE_DIR "/datasets/scenarios/valley.ini"); }

size_t rocks(const World& w)
{
  size_t n = 0;
  for (const Shape& s : w.shapes) n += s.kind == ShapeKind::Rock;
  return n;
}
}  // namespace

TEST(SimChanges, RocksTakenAwayAndPutInTheBandTheSameForASeed)
{
  Scenario sc = valley();
  const VehiclePath path(sc.vehicle.waypoints, sc.vehicle.closed, sc.vehicle.speed);
  const World original = generateWorld(sc, path);
  sc.changes.remove = 2;
  sc.changes.add = 3;
  sc.changes.seed = 5;
  World changed = original;
  const auto changes = applyChanges(changed, sc.changes, path);
  ASSERT_EQ(changes.size(), 5u);
  EXPECT_EQ(rocks(changed), rocks(original) - 2 + 3);
  EXPECT_EQ(changed.shapes.size(), original.shapes.size() + 1);
  for (const WorldChange& c : changes)
  {
    EXPECT_EQ(c.added, &c >= &changes[2]);
    if (c.added)
    {
      EXPECT_EQ(c.radius, sc.changes.radius);
      EXPECT_TRUE(changed.isWater(c.center));
    }
    else
      EXPECT_GE(c.radius, 0.5);
  }
  World again = original;
  const auto same = applyChanges(again, sc.changes, path);
  for (size_t k = 0; k < changes.size(); k++) EXPECT_EQ(same[k].center, changes[k].center);
  // A world with no change asked is left as it is.
  World untouched = original;
  EXPECT_TRUE(applyChanges(untouched, ChangesParams(), path).empty());
  EXPECT_EQ(untouched.shapes.size(), original.shapes.size());
}

TEST(SimChanges, MoreRocksThanTheBandHoldsIsANamedErrorAndTheSectionRoundTrips)
{
  Scenario sc = valley();
  const VehiclePath path(sc.vehicle.waypoints, sc.vehicle.closed, sc.vehicle.speed);
  World world = generateWorld(sc, path);
  sc.changes.remove = 50;
  try
  {
    applyChanges(world, sc.changes, path);
    FAIL() << "accepted";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("[changes] remove = 50, but only"), std::string::npos) << e.what();
  }
  sc.changes.remove = 1;
  sc.changes.add = 2;
  const std::string file = swslam::test::tempDir("sim_changes_rt") + "/changed.ini";
  swslam::test::writeText(file, formatScenario(sc));
  const Scenario back = loadScenario(file);
  EXPECT_EQ(back.changes.remove, 1u);
  EXPECT_EQ(back.changes.add, 2u);
  EXPECT_EQ(formatScenario(back), formatScenario(sc));
}

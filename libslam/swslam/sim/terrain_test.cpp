// The low bank: a shore segment is seen only from the water, a ray passes over it with
// [terrain] bank_pass_through, and then the land vegetation behind it shows up.
#include "sim_test_scenario.h"

#include <swslam/sim/grid.h>
#include <swslam/sim/terrain.h>
#include <swslam/sim/vehicle.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace swslam::sim;

TEST(SimBank, SeenOnlyFromTheWaterSide)
{
  // Water on the left of a -> b: the bank from (3, -1) to (3, 2) faces -x.
  const Shape bank = Shape::bank({3, -1}, {3, 2}, 0);
  Ray from_water;
  from_water.origin = {0, 0};
  from_water.dir = {1, 0};
  EXPECT_NEAR(hitDistance(bank, from_water), 3.0, 1e-12);
  Ray from_land;
  from_land.origin = {6, 0};
  from_land.dir = {-1, 0};
  EXPECT_EQ(hitDistance(bank, from_land), kNoHit);
  // The same segment without a side is seen from both.
  EXPECT_NEAR(hitDistance(Shape::segment(ShapeKind::Bank, {3, -1}, {3, 2}), from_land), 3.0, 1e-12);
  // Reversed, it faces +x.
  EXPECT_EQ(hitDistance(Shape::bank({3, 2}, {3, -1}, 0), from_water), kNoHit);
  EXPECT_NEAR(hitDistance(Shape::bank({3, 2}, {3, -1}, 0), from_land), 3.0, 1e-12);
}

TEST(SimBank, PassedWithItsProbability)
{
  const Shape bank = Shape::bank({3, 2}, {3, -1}, 0.4);
  Ray r;
  int passed = 0;
  const int n = 20000;
  for (int k = 0; k < n; k++)
  {
    r.key = mix64(k);
    passed += passesThrough(bank, 11, r);
  }
  EXPECT_NEAR(static_cast<double>(passed) / n, 0.4, 0.02);
  EXPECT_FALSE(passesThrough(Shape::bank({3, 2}, {3, -1}, 0), 11, r));
}

TEST(SimBank, GeneratedShoresFaceTheWater)
{
  // Lake and island banks alike: just left of each segment (its seen side) is water,
  // just right of it is land.
  Scenario sc = swslam::test::smallScenario();
  sc.terrain.island_center_x = 0;
  sc.terrain.island_center_y = -18;
  sc.terrain.island_radius = 4;
  sc.terrain.island_roughness = 0.5;
  const VehiclePath path(sc.vehicle.waypoints, sc.vehicle.closed, sc.vehicle.speed);
  const World world = generateWorld(sc, path);
  ASSERT_EQ(world.islands.size(), 1u);
  size_t banks = 0, island_banks = 0;
  for (const auto& s : world.shapes)
  {
    if (s.kind != ShapeKind::Bank) continue;
    ASSERT_TRUE(s.one_sided);
    EXPECT_DOUBLE_EQ(s.pass_through, 0.5);
    const Eigen::Vector2d e = (s.b - s.a).normalized(), left(-e.y(), e.x());
    const Eigen::Vector2d mid = 0.5 * (s.a + s.b);
    // 0.7 m: beyond the 0.3 m jitter of the segments around the smooth shore.
    EXPECT_TRUE(world.isWater(mid + 0.7 * left)) << mid.transpose();
    EXPECT_FALSE(world.isWater(mid - 0.7 * left)) << mid.transpose();
    banks++;
    island_banks += world.islands[0].radialOffset(mid) < 1.0;
  }
  EXPECT_GT(banks, 50u);
  EXPECT_GT(island_banks, 20u);
}

namespace
{
/** Of rays cast all around from points along the path, the fraction that return from
 * more than 1 m inside the land, behind the shore line (the bank's own segments lie
 * within 0.3 m of it). */
double fractionFromBehindTheBank(double bank_pass_through, double& any_hit)
{
  Scenario sc = swslam::test::smallScenario();
  sc.terrain.bank_pass_through = bank_pass_through;
  const VehiclePath path(sc.vehicle.waypoints, sc.vehicle.closed, sc.vehicle.speed);
  const World world = generateWorld(sc, path);
  const ShapeGrid grid(world, sc.world.grid_cell);
  size_t rays = 0, hits = 0, behind = 0;
  for (double t = 0; t < path.duration(); t += 0.5)
  {
    const auto pose = path.poseAt(t);
    for (int i = 0; i < 720; i++, rays++)
    {
      Ray r;
      r.origin = {pose.x(), pose.y()};
      const double a = 2 * M_PI * i / 720;
      r.dir = {std::cos(a), std::sin(a)};
      r.key = mix64(rays);
      const double d = grid.cast(r, 40.0);
      if (d == kNoHit) continue;
      hits++;
      behind += world.lake.radialOffset(r.origin + d * r.dir) > 1.0;
    }
  }
  any_hit = static_cast<double>(hits) / rays;
  return static_cast<double>(behind) / rays;
}
}  // namespace

TEST(SimBank, LandVegetationVisibleOnlyOverAPassableBank)
{
  double hits_opaque = 0, hits_low = 0;
  EXPECT_EQ(fractionFromBehindTheBank(0.0, hits_opaque), 0.0);
  const double behind = fractionFromBehindTheBank(0.5, hits_low);
  EXPECT_GT(behind, 0.05);  // trunks and bushes on the land return (12% of the rays)
  EXPECT_LT(hits_low, hits_opaque);  // some rays pass the bank and every shape behind it
  // A bank that every ray passes: all that returns from the land is vegetation.
  double hits_none = 0;
  EXPECT_GT(fractionFromBehindTheBank(1.0, hits_none), behind);
}

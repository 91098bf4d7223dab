// The grid-accelerated ray cast against the brute-force loop over every shape.
#include "sim_test_scenario.h"

#include <swslam/sim/grid.h>
#include <swslam/sim/terrain.h>
#include <swslam/sim/vehicle.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace swslam::sim;

namespace
{
/** Random shapes of every kind, sizes and pass-through, one-sided banks, some shapes on
 * cell borders. */
World randomWorld(unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  World w;
  w.bounds = {-20, -15, 20, 15};
  for (int i = 0; i < 300; i++)
  {
    const Eigen::Vector2d c(-19 + 38 * U(rng), -14 + 28 * U(rng));
    if (U(rng) < 0.5)
    {
      const double pass = U(rng) < 0.5 ? 0.0 : 0.6;
      w.add(Shape::circle(U(rng) < 0.5 ? ShapeKind::Trunk : ShapeKind::Bush, c,
                          0.01 + 0.6 * U(rng), pass));
    }
    else
    {
      const double a = 2 * M_PI * U(rng), len = 0.1 + 4 * U(rng);
      const Eigen::Vector2d b = c + len * Eigen::Vector2d(std::cos(a), std::sin(a));
      const double kind = U(rng);  // two-sided, or a one-sided bank opaque or passable
      w.add(kind < 0.4 ? Shape::segment(ShapeKind::Bank, c, b)
                       : Shape::bank(c, b, kind < 0.7 ? 0.0 : 0.5));
    }
  }
  // Axis-aligned segments exactly on cell borders (cell size 2).
  w.add(Shape::segment(ShapeKind::Bank, {4, -10}, {4, 10}));
  w.add(Shape::segment(ShapeKind::Bank, {-10, 6}, {10, 6}));
  return w;
}

void expectSameAsBruteForce(const World& w, double cell, unsigned seed, double max_range)
{
  const ShapeGrid grid(w, cell);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  size_t hits = 0;
  for (int i = 0; i < 20000; i++)
  {
    Ray r;
    r.origin = {w.bounds.min_x + (w.bounds.max_x - w.bounds.min_x) * U(rng),
                w.bounds.min_y + (w.bounds.max_y - w.bounds.min_y) * U(rng)};
    // Every 10th ray is axis-aligned: the DDA's degenerate directions.
    const double a = i % 10 == 0 ? (i / 10 % 4) * M_PI / 2 : 2 * M_PI * U(rng);
    r.dir = {std::cos(a), std::sin(a)};
    r.key = rng();
    const double slow = castBruteForce(w, r, max_range);
    const double fast = grid.cast(r, max_range);
    if (slow == kNoHit)
      ASSERT_EQ(fast, kNoHit) << "ray " << i;
    else
      ASSERT_NEAR(fast, slow, 1e-9) << "ray " << i;
    hits += slow != kNoHit;
  }
  EXPECT_GT(hits, 5000u);  // the comparison covered many hits, not just misses
}
}  // namespace

TEST(SimGrid, CastEqualsBruteForceOnRandomRays)
{
  const World w = randomWorld(1);
  for (double cell : {0.5, 2.0, 7.0}) expectSameAsBruteForce(w, cell, 2, 30.0);
  expectSameAsBruteForce(w, 2.0, 3, 3.0);  // short range: many rays end in open cells
}

TEST(SimGrid, CastEqualsBruteForceInGeneratedWorld)
{
  const Scenario sc = swslam::test::smallScenario();
  const VehiclePath path(sc.vehicle.waypoints, sc.vehicle.closed, sc.vehicle.speed);
  const World w = generateWorld(sc, path);
  ASSERT_GT(w.shapes.size(), 200u);
  expectSameAsBruteForce(w, sc.world.grid_cell, 4, 25.0);
}

TEST(SimWorld, HitDistanceClosedForms)
{
  Ray r;
  r.origin = {0, 0};
  r.dir = {1, 0};
  EXPECT_NEAR(hitDistance(Shape::circle(ShapeKind::Trunk, {5, 0}, 1), r), 4.0, 1e-12);
  EXPECT_NEAR(hitDistance(Shape::circle(ShapeKind::Trunk, {5, 0.6}, 1), r), 4.2, 1e-12);
  EXPECT_EQ(hitDistance(Shape::circle(ShapeKind::Trunk, {5, 1.5}, 1), r), kNoHit);
  EXPECT_EQ(hitDistance(Shape::circle(ShapeKind::Trunk, {-5, 0}, 1), r), kNoHit);  // behind
  EXPECT_EQ(hitDistance(Shape::circle(ShapeKind::Trunk, {0.5, 0}, 1), r), kNoHit);  // inside
  EXPECT_NEAR(hitDistance(Shape::segment(ShapeKind::Bank, {3, -1}, {3, 2}), r), 3.0, 1e-12);
  EXPECT_EQ(hitDistance(Shape::segment(ShapeKind::Bank, {3, 1}, {3, 2}), r), kNoHit);
}

TEST(SimWorld, PassThroughFrequencyMatchesProbability)
{
  const Shape bush = Shape::circle(ShapeKind::Bush, {3, 0}, 0.5, 0.3);
  Ray r;
  int passed = 0;
  const int n = 20000;
  for (int k = 0; k < n; k++)
  {
    r.key = swslam::sim::mix64(k);
    passed += passesThrough(bush, 7, r);
    ASSERT_EQ(passesThrough(bush, 7, r), passesThrough(bush, 7, r));  // a pure function
  }
  EXPECT_NEAR(static_cast<double>(passed) / n, 0.3, 0.02);
  EXPECT_FALSE(passesThrough(Shape::circle(ShapeKind::Trunk, {3, 0}, 0.5), 7, r));
}

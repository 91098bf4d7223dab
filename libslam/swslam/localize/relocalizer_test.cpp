#include <swslam/localize/relocalizer.h>

#include <swslam/correlative/score_grid.h>

#include <gtest/gtest.h>

#include "support/localize_test_support.h"

using namespace swslam;
using mrpt::poses::CPose2D;

namespace
{
std::vector<CPose2D> roomPath()
{
  std::vector<CPose2D> p;
  for (double x = -8; x <= 8; x += 1.0) p.emplace_back(x, -1.0, 0.1 * x);
  for (double x = 5; x >= -8; x -= 1.0) p.emplace_back(x, 3.0, M_PI);
  return p;
}

std::vector<Eigen::Vector2d> searchPoints(const test::World& world, const CPose2D& vehicle, unsigned seed)
{
  std::mt19937 rng(seed);
  const auto obs = test::localizeObservation(world, vehicle, rng, 0);
  return correlative::thinPoints(sensor::scanFromObservation(*obs).points, 0.1, 30);
}
}  // namespace

TEST(Relocalizer, FindsAScanAnywhereInTheRoomAtAnyHeading)
{
  const auto m = test::savedWorldMap(test::roomWorld(), roomPath());
  const localize::Relocalizer r(m.grid, 0.65, 0.196, localize::LocalizationParams());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(-8, 5), uy(-4, 4), ut(-M_PI, M_PI);
  int found = 0;
  for (int k = 0; k < 10; ++k)
  {
    const CPose2D vehicle(ux(rng), uy(rng), ut(rng));
    const auto place = r.find(searchPoints(test::roomWorld(), vehicle, 100 + k));
    ASSERT_TRUE(place) << vehicle;
    const CPose2D sensor = vehicle + CPose2D(0.3, 0, 0);
    if (!place->distinct) continue;
    found++;
    EXPECT_NEAR(place->pose.x(), sensor.x(), 0.25) << vehicle;
    EXPECT_NEAR(place->pose.y(), sensor.y(), 0.25) << vehicle;
    EXPECT_NEAR(std::remainder(place->pose.z() - sensor.phi(), 2 * M_PI), 0, 0.03) << vehicle;
    EXPECT_LT(place->second, place->score);
  }
  EXPECT_GE(found, 9);
}

TEST(Relocalizer, ACorridorIsNoDistinctPlace)
{
  std::vector<CPose2D> path;
  for (double x = -12; x <= 12; x += 1.0) path.emplace_back(x, 0, 0);
  const auto m = test::savedWorldMap(test::corridorWorld(), path);
  const localize::Relocalizer r(m.grid, 0.65, 0.196, localize::LocalizationParams());
  const auto place = r.find(searchPoints(test::corridorWorld(), CPose2D(1, 0, 0), 3));
  ASSERT_TRUE(place);
  EXPECT_FALSE(place->distinct);
  EXPECT_GT(place->second, 0.85 * place->score);
}

TEST(Relocalizer, AnotherPlaceScoresBelowTheThreshold)
{
  const auto m = test::savedWorldMap(test::roomWorld(), roomPath());
  const localize::Relocalizer r(m.grid, 0.65, 0.196, localize::LocalizationParams());
  const auto place = r.find(searchPoints(test::clutteredWorld(5), CPose2D(0, 0, 0), 4));
  EXPECT_TRUE(!place || !place->distinct);
}

TEST(Relocalizer, AMapWithNoObstacleIsRefused)
{
  mrpt::maps::COccupancyGridMap2D empty(-5, 5, -5, 5, 0.1f);
  EXPECT_THROW(localize::Relocalizer(empty, 0.65, 0.196, localize::LocalizationParams()), std::invalid_argument);
}

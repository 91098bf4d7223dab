#include <swslam/localize/localizer.h>

#include <gtest/gtest.h>

#include "support/localize_test_support.h"

using namespace swslam;
using mrpt::poses::CPose2D;

namespace
{
std::vector<CPose2D> mapPath()
{
  std::vector<CPose2D> p;
  for (double x = -8; x <= 8; x += 0.5) p.emplace_back(x, -1.0, 0);
  for (double x = 5; x >= -8; x -= 0.5) p.emplace_back(x, 3.0, M_PI);
  return p;
}

/** The second run: along the room's middle at 0.1 m a scan, slightly turning. */
std::vector<CPose2D> secondPath()
{
  std::vector<CPose2D> p;
  for (int k = 0; k < 80; ++k) p.emplace_back(-6 + 0.1 * k, 1.0 + 0.5 * std::sin(0.05 * k), 0.3 * std::sin(0.03 * k));
  return p;
}

struct Fixture
{
  test::SavedWorldMap saved = test::savedWorldMap(test::roomWorld(), mapPath());
  localize::MapNodes nodes{saved.poses, saved.scans, plicp::PlicpParams()};
  localize::Relocalizer relocalizer{saved.grid, 0.65, 0.196, localize::LocalizationParams()};
  localize::LocalizerParams params;
};

sensor::ScanInput input(const test::World& world, const CPose2D& vehicle, std::mt19937& rng, double stamp)
{
  return {test::localizeObservation(world, vehicle, rng, stamp), std::nullopt};
}
}  // namespace

TEST(Localizer, RelocalizesWithNoInitialPoseThenTracks)
{
  Fixture f;
  localize::Localizer loc(f.nodes, f.relocalizer, f.params);
  std::mt19937 rng(11);
  const auto path = secondPath();
  size_t relocalized = 0, tracked = 0;
  for (size_t k = 0; k < path.size(); ++k)
  {
    const auto r = loc.localize(input(test::roomWorld(), path[k], rng, 2000 + 0.1 * k));
    if (k == 0) EXPECT_EQ(r.state, localize::LocalizationState::Relocalized);
    if (r.state == localize::LocalizationState::Relocalized) relocalized++;
    if (r.state == localize::LocalizationState::Tracked) tracked++;
    if (r.state == localize::LocalizationState::Lost) continue;
    EXPECT_NEAR(r.pose.x(), path[k].x(), 0.03) << k;
    EXPECT_NEAR(r.pose.y(), path[k].y(), 0.03) << k;
    EXPECT_NEAR(r.pose.phi(), path[k].phi(), 0.005) << k;
    EXPECT_GT(r.inlier_fraction, 0.5);
    EXPECT_GT(r.map_score, 0.5);
    EXPECT_LT(r.covariance(0, 0), 1e-3);
  }
  EXPECT_EQ(relocalized, 1u);
  EXPECT_EQ(tracked, path.size() - 1);
}

TEST(Localizer, AnInitialPoseIsTrackedFrom)
{
  Fixture f;
  localize::Localizer loc(f.nodes, f.relocalizer, f.params);
  const auto path = secondPath();
  loc.setInitialPose(path[0] + CPose2D(0.2, -0.1, 0.03));
  std::mt19937 rng(12);
  const auto r = loc.localize(input(test::roomWorld(), path[0], rng, 3000));
  EXPECT_EQ(r.state, localize::LocalizationState::Tracked);
  EXPECT_FALSE(r.searched_map);
  EXPECT_NEAR(r.pose.x(), path[0].x(), 0.03);
}

TEST(Localizer, ScansOfAnotherPlaceAreLostNeverPlaced)
{
  Fixture f;
  localize::Localizer loc(f.nodes, f.relocalizer, f.params);
  std::mt19937 rng(13);
  const test::World elsewhere = test::clutteredWorld(9);
  size_t searched = 0;
  for (int k = 0; k < 40; ++k)
  {
    const auto r = loc.localize(input(elsewhere, CPose2D(-5 + 0.25 * k, 0, 0), rng, 4000 + 0.1 * k));
    EXPECT_EQ(r.state, localize::LocalizationState::Lost) << k;
    EXPECT_TRUE(std::isinf(r.covariance(0, 0)));
    searched += r.searched_map;
  }
  // One whole-map search at least relocalize_interval (0.25 s) of log after the last: at
  // every third scan 0.1 s apart, 14 in 40 scans.
  EXPECT_EQ(searched, 14u);
}

TEST(Localizer, UnmatchedForLostAfterSecondsIsLostThenRelocalizes)
{
  Fixture f;
  localize::Localizer loc(f.nodes, f.relocalizer, f.params);
  std::mt19937 rng(14);
  const auto path = secondPath();
  ASSERT_NE(loc.localize(input(test::roomWorld(), path[0], rng, 5000)).state, localize::LocalizationState::Lost);
  // A blind sensor (every ray invalid) for 1.5 s: predicted, then lost after lost_after (1 s).
  std::vector<localize::LocalizationState> states;
  for (int k = 1; k <= 15; ++k)
  {
    auto obs = test::localizeObservation(test::roomWorld(), path[0], rng, 5000 + 0.1 * k);
    for (size_t i = 0; i < obs->getScanSize(); ++i) obs->setScanRangeValidity(i, false);
    states.push_back(loc.localize({obs, std::nullopt}).state);
  }
  EXPECT_EQ(states[0], localize::LocalizationState::Predicted);
  EXPECT_EQ(states[9], localize::LocalizationState::Predicted);  // 1.0 s: not yet
  EXPECT_EQ(states[10], localize::LocalizationState::Lost);      // 1.1 s
  EXPECT_EQ(states.back(), localize::LocalizationState::Lost);
  // The sensor sees again: relocalized at the next whole-map search (the last ones at 1.1
  // and 1.4 s, one every 0.25 s of log).
  EXPECT_EQ(loc.localize(input(test::roomWorld(), path[1], rng, 5001.6)).state, localize::LocalizationState::Lost);
  const auto r = loc.localize(input(test::roomWorld(), path[1], rng, 5001.7));
  EXPECT_EQ(r.state, localize::LocalizationState::Relocalized);
  EXPECT_NEAR(r.pose.x(), path[1].x(), 0.03);
}

TEST(Localizer, AnotherSensorLabelAndMountingMatchTheMap)
{
  // The map's scans are LASER's (simulateObservation's label), 541 rays mounted 0.3 m ahead; the
  // log's come from a scanner named otherwise, mounted elsewhere, with fewer rays.
  Fixture f;
  localize::Localizer loc(f.nodes, f.relocalizer, f.params);
  std::mt19937 rng(15);
  const CPose2D mount(-0.2, 0.1, 0.3), vehicle(-3, 1.5, 0.4);
  auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>(
      test::simulateObservation(test::roomWorld(), vehicle + mount, 361, 1.5 * M_PI, 30, 0.01, rng));
  obs->sensorLabel = "HOKUYO_UTM";
  obs->sensorPose = mrpt::poses::CPose3D(mount);
  obs->timestamp = mrpt::Clock::fromDouble(6000);
  const auto r = loc.localize({obs, std::nullopt});
  ASSERT_EQ(r.state, localize::LocalizationState::Relocalized);
  EXPECT_NEAR(r.pose.x(), vehicle.x(), 0.03);
  EXPECT_NEAR(r.pose.y(), vehicle.y(), 0.03);
  EXPECT_NEAR(r.pose.phi(), vehicle.phi(), 0.005);
}

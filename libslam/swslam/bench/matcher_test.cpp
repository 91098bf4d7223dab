// The matcher benchmark (swslam-bench-matcher): its rows on a synthetic walk through a room,
// and the floor of a full-resolution PLICP match.
#include "test_support.h"

#include <swslam/bench/matcher.h>

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace
{
using mrpt::poses::CPose2D;

/** Scans every 0.2 m and 2 deg along a straight walk through the room, with their poses. */
swslam::io::ScansWithTruth roomWalk(size_t n)
{
  const auto world = swslam::test::roomWorld();
  std::mt19937 rng(7);
  swslam::io::ScansWithTruth data;
  for (size_t k = 0; k < n; k++)
  {
    const CPose2D pose(-3.0 + 0.2 * k, -1.0 + 0.05 * k, 0.035 * k);
    auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>(
        swslam::test::simulateObservation(world, pose, 361, M_PI, 30, 0.01, rng));
    data.scans.push_back(obs);
    data.truth.push_back(pose);
  }
  return data;
}
}  // namespace

TEST(MatcherBenchmark, RowsOfEveryMethodFromBothGuesses)
{
  const auto data = roomWalk(6);
  const auto rows = swslam::bench::benchmarkMatchers(data, 1, swslam::plicp::PlicpParams());
  ASSERT_EQ(rows.size(), 8u);  // 4 methods x 2 guesses
  for (const auto& r : rows)
  {
    EXPECT_EQ(r.pairs, 5u) << r.method;
    EXPECT_GT(r.median_us, 0.0) << r.method;
    if (r.init == "reference" && r.method.rfind("plicp", 0) == 0)
    {
      EXPECT_LT(r.trans_rmse_m, 0.02) << r.method;
      EXPECT_EQ(r.failures, 0u) << r.method;
    }
  }
  EXPECT_EQ(swslam::bench::benchmarkMatchers(data, 2, swslam::plicp::PlicpParams(), "plicp").size(), 2u);
  EXPECT_EQ(swslam::bench::benchmarkMatchers(data, 2, swslam::plicp::PlicpParams(), "plicp").front().pairs, 2u);
  EXPECT_THROW(swslam::bench::benchmarkMatchers(data, 1, swslam::plicp::PlicpParams(), "plicp2"),
               std::invalid_argument);
}

TEST(MatcherBenchmark, FloorTimesEachPartAndTheirSum)
{
  const auto data = roomWalk(6);
  const swslam::bench::PlicpFloor f = swslam::bench::plicpFloor(data, 1, swslam::plicp::PlicpParams());
  EXPECT_EQ(f.pairs, 5u);
  EXPECT_GT(f.conversion_us, 0.0);
  EXPECT_GT(f.index_us, 0.0);
  EXPECT_GT(f.search_us, 0.0);
  // Each pair's sum is at least each of its parts, so the medians keep that order.
  EXPECT_GE(f.total_us, f.conversion_us);
  EXPECT_GE(f.total_us, f.index_us);
  EXPECT_GE(f.total_us, f.search_us);
  EXPECT_EQ(swslam::bench::plicpFloor(data, 3, swslam::plicp::PlicpParams()).pairs, 1u);
  EXPECT_NE(swslam::bench::formatFloor(f).find("plicp-floor   init=reference pairs=5 median_us="),
            std::string::npos);
}

TEST(MatcherBenchmark, SearchFloorTimesThePartsOfTheSearchedPairs)
{
  // Steps of 0.2 m and 2 deg: from identity PLICP moves every guess by more than the search's
  // trigger (0.1 m), so every pair is searched.
  const auto data = roomWalk(6);
  swslam::tracking::TrackingParams trigger_only;
  trigger_only.search_first_match = false;
  const swslam::bench::SearchFloor f = swslam::bench::searchFloor(data, 1, swslam::plicp::PlicpParams(),
                                                                  swslam::correlative::CorrelativeParams(), trigger_only);
  EXPECT_EQ(f.pairs, 5u);
  EXPECT_EQ(f.searched, 5u);
  EXPECT_GT(f.plicp_us, 0.0);
  EXPECT_GT(f.grid_us, 0.0);
  EXPECT_GT(f.bnb_us, 0.0);
  EXPECT_GE(f.total_us, f.plicp_us);
  EXPECT_GE(f.total_us, f.grid_us);
  EXPECT_GE(f.total_us, f.bnb_us);
  // A search that never triggers: no pair is searched, and no time is reported, unless
  // identity, a guess, is searched as tracking searches a run's first match.
  swslam::correlative::CorrelativeParams never;
  never.trigger_correction_xy = 100;
  never.trigger_correction_theta = 10;
  never.trigger_inlier_fraction = 0;
  const swslam::bench::SearchFloor none =
      swslam::bench::searchFloor(data, 1, swslam::plicp::PlicpParams(), never, trigger_only);
  EXPECT_EQ(none.pairs, 5u);
  EXPECT_EQ(none.searched, 0u);
  EXPECT_EQ(none.total_us, 0.0);
  EXPECT_EQ(swslam::bench::searchFloor(data, 1, swslam::plicp::PlicpParams(), never).searched, 5u);
  EXPECT_NE(swslam::bench::formatSearchFloor(f).find("search-floor  init=identity  pairs=5 searched=5 median_us="),
            std::string::npos);
}

TEST(MatcherBenchmark, FromIdentityPlicpSearchSearchesTheGuessAsTrackingDoes)
{
  // A corridor with an end wall, scanned every 1 m: from identity PLICP can keep the guess (the
  // walls agree at any shift, and most points stay inliers), and the trigger alone does not
  // search it. Identity is a guess, not a measured prediction: searched, as tracking searches
  // a run's first match (search_first_match), every step comes from the end wall.
  auto world = swslam::test::corridorWorld();
  world.segments.push_back({6, -1, 6, 1});
  std::mt19937 rng(3);
  swslam::io::ScansWithTruth data;
  for (int k = 0; k < 4; k++)
  {
    const CPose2D pose(1.0 * k, 0, 0);
    data.scans.push_back(std::make_shared<mrpt::obs::CObservation2DRangeScan>(
        swslam::test::simulateObservation(world, pose, 181, M_PI, 8, 0.01, rng)));
    data.truth.push_back(pose);
  }
  auto row = [&](bool search_guesses, const std::string& init) {
    swslam::tracking::TrackingParams tracking;
    tracking.search_first_match = search_guesses;
    for (const auto& r : swslam::bench::benchmarkMatchers(data, 1, swslam::plicp::PlicpParams(), "plicp+search",
                                                          swslam::correlative::CorrelativeParams(), tracking))
      if (r.init == init) return r;
    ADD_FAILURE() << "no " << init << " row";
    return swslam::bench::MatcherRow{};
  };
  const auto searched = row(true, "identity");
  EXPECT_EQ(searched.searched, 3u);
  EXPECT_EQ(searched.frac_under_5cm, 1.0);
  const auto trigger_only = row(false, "identity");
  EXPECT_LT(trigger_only.searched, 3u);
  EXPECT_LT(trigger_only.frac_under_5cm, 1.0) << "PLICP keeps the guess along the corridor";
  // The reference motion is measured: searching guesses changes nothing there.
  EXPECT_EQ(row(true, "reference").searched, row(false, "reference").searched);
  EXPECT_NE(swslam::bench::formatRow(searched).find(" searched=3"), std::string::npos);
}

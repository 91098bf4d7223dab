// The matcher benchmark (swslam-bench-matcher): its rows on a synthetic walk through a room,
// and the floor of a full-resolution PLICP match.
#include "test_support.h"

#include <swslam/bench/matcher.h>
#include <swslam/correlative/search.h>

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace
{
using mrpt::poses::CPose2D;

/** Scans of `beams` rays over 180 deg taken at `poses` in `world`, with the poses as their truth. */
swslam::io::ScansWithTruth scansAt(const swslam::test::World& world, const std::vector<CPose2D>& poses, size_t beams,
                                   double max_range, double noise, unsigned seed)
{
  std::mt19937 rng(seed);
  swslam::io::ScansWithTruth data;
  for (const CPose2D& pose : poses)
  {
    data.scans.push_back(std::make_shared<mrpt::obs::CObservation2DRangeScan>(
        swslam::test::simulateObservation(world, pose, beams, M_PI, max_range, noise, rng)));
    data.truth.push_back(pose);
  }
  return data;
}

/** Scans every 0.2 m and 2 deg along a straight walk through the room, with their poses. */
swslam::io::ScansWithTruth roomWalk(size_t n)
{
  std::vector<CPose2D> poses;
  for (size_t k = 0; k < n; k++) poses.emplace_back(-3.0 + 0.2 * k, -1.0 + 0.05 * k, 0.035 * k);
  return scansAt(swslam::test::roomWorld(), poses, 361, 30, 0.01, 7);
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
  // Where the branch and bound's work lies: the pyramid's levels for the default window, each
  // level's candidates the children of splits above it, and the top's every angle's blocks.
  const swslam::correlative::CorrelativeParams defaults;
  ASSERT_EQ(f.evaluated_by_level.size(),
            static_cast<size_t>(swslam::correlative::depthForWindow(defaults.window_xy, defaults.resolution)) + 1);
  EXPECT_DOUBLE_EQ(f.evaluated_by_level.back(), 360.0);
  double total = 0;
  for (size_t h = 0; h < f.evaluated_by_level.size(); h++)
  {
    total += f.evaluated_by_level[h];
    if (h + 1 < f.evaluated_by_level.size()) EXPECT_LE(f.evaluated_by_level[h], 4 * f.expanded_by_level[h + 1] + 1e-9);
  }
  EXPECT_GT(f.evaluated_median, 360.0);
  EXPECT_LT(f.evaluated_median, 2 * total);
  EXPECT_NE(swslam::bench::formatSearchFloor(f).find("by_level="), std::string::npos);
  // A search that never triggers: no pair is searched, and no time is reported, unless
  // identity, a guess, is searched as tracking searches a run's first match.
  swslam::tracking::TrackingParams never = trigger_only;
  never.trigger_correction_xy = 100;
  never.trigger_correction_theta = 10;
  never.trigger_inlier_fraction = 0;
  const swslam::bench::SearchFloor none =
      swslam::bench::searchFloor(data, 1, swslam::plicp::PlicpParams(), swslam::correlative::CorrelativeParams(), never);
  EXPECT_EQ(none.pairs, 5u);
  EXPECT_EQ(none.searched, 0u);
  EXPECT_EQ(none.total_us, 0.0);
  never.search_first_match = true;
  EXPECT_EQ(swslam::bench::searchFloor(data, 1, swslam::plicp::PlicpParams(), swslam::correlative::CorrelativeParams(), never)
                .searched,
            5u);
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
  const auto data = scansAt(world, {CPose2D(0, 0, 0), CPose2D(1, 0, 0), CPose2D(2, 0, 0), CPose2D(3, 0, 0)}, 181, 8,
                            0.01, 3);
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

namespace
{
/** explainMisses() of the plicp+search row from identity on `data`, pairs (k, k + 1). */
swslam::bench::MissExplanation missesOf(const swslam::io::ScansWithTruth& data,
                                        const swslam::correlative::CorrelativeParams& search)
{
  for (const auto& r : swslam::bench::benchmarkMatchers(data, 1, swslam::plicp::PlicpParams(), "plicp+search", search))
    if (r.init == "identity") return swslam::bench::explainMisses(data, 1, r, swslam::plicp::PlicpParams(), search);
  ADD_FAILURE() << "no plicp+search row from identity";
  return {};
}
}  // namespace

TEST(MatcherBenchmark, MissesAreSupportedOnlyWhereThePairFavoursTheReference)
{
  // Without the search, PLICP from identity misses turns of 60 deg in the room, and each
  // pair's own scans support the reference: PLICP from it stays, with more inliers than at the
  // pose it chose.
  std::vector<CPose2D> turns;
  for (int k = 0; k < 4; k++) turns.emplace_back(-2.0 + 0.5 * k, 0.2 * k, 1.05 * k);
  const auto room = scansAt(swslam::test::roomWorld(), turns, 361, 30, 0.01, 7);
  swslam::correlative::CorrelativeParams off;
  off.enabled = false;
  const auto plain = missesOf(room, off);
  EXPECT_EQ(plain.pairs, 3u);
  EXPECT_EQ(plain.misses, 3u);
  EXPECT_EQ(plain.supported, 3u);
  EXPECT_DOUBLE_EQ(plain.best_share, 1.0);
  // With the search, no misses.
  const auto searched = missesOf(room, swslam::correlative::CorrelativeParams());
  EXPECT_EQ(searched.misses, 0u);
  EXPECT_DOUBLE_EQ(searched.best_share, 1.0);

  // Two parallel walls and nothing else, scanned every 1 m: every pose along them fits as well
  // as the reference, so no miss is supported (PLICP from either keeps it, with the same inliers
  // and score), and the best share is what the matcher got.
  const auto walls = scansAt(swslam::test::corridorWorld(),
                             {CPose2D(0, 0, 0), CPose2D(1, 0, 0), CPose2D(2, 0, 0), CPose2D(3, 0, 0)}, 181, 8, 0.0, 5);
  const auto along = missesOf(walls, off);
  EXPECT_EQ(along.misses, 3u);
  EXPECT_EQ(along.supported, 0u);
  EXPECT_DOUBLE_EQ(along.best_share, 0.0);
  EXPECT_NE(swslam::bench::formatMisses(along).find("misses        init=identity  pairs=3 misses=3 supported=0 "
                                                     "best_frac_under_5cm=0.000"),
            std::string::npos);
  // Another row, or one from another stride, is refused.
  const auto rows = swslam::bench::benchmarkMatchers(walls, 1, swslam::plicp::PlicpParams(), "plicp+search", off);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_THROW(swslam::bench::explainMisses(walls, 1, rows[1], swslam::plicp::PlicpParams(), off), std::invalid_argument);
  EXPECT_THROW(swslam::bench::explainMisses(walls, 2, rows[0], swslam::plicp::PlicpParams(), off), std::invalid_argument);
}

// Tracking's scan matcher and its rules around the correlative search (scan_matcher.h,
// search_policy.h).
#include <swslam/correlative/search_setup.h>
#include <swslam/tracking/scan_matcher.h>
#include <swslam/tracking/search_policy.h>

#include <Eigen/LU>
#include <Eigen/QR>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::tracking;
using correlative::MatchComparison;
using correlative::ScoreGrid;
using correlative::ScorePyramid;
using correlative::SearchWindow;
using mrpt::poses::CPose2D;

namespace
{
/** A CARMEN-like scan: 181 beams over 180 deg, 30 m. */
sensor::Scan scanAt(const test::World& world, const CPose2D& pose, std::mt19937& rng)
{
  return sensor::scanFromObservation(test::simulateObservation(world, pose, 181, M_PI, 30, 0.02, rng));
}

bool predictionFailed(const plicp::MatchResult& m, const CPose2D& guess, const TrackingParams& p)
{
  return searchTrigger(m, guess, p) != SearchTrigger::None;
}

/** searchAndChoose() against `ref` alone, the search's grid holding the rays of `grid_scan`. */
SearchedMatch searchAgainst(const plicp::ReferenceScan& ref, const sensor::Scan& grid_scan, const sensor::Scan& cur,
                            const CPose2D& guess, const plicp::MatchResult& first, const TrackingParams& tp,
                            const plicp::PlicpParams& plicp, const correlative::CorrelativeParams& cp = {},
                            double prediction_variance = std::numeric_limits<double>::infinity())
{
  const Submap submap(std::make_shared<const plicp::ReferenceScan>(ref),
                      [&] { return correlative::scanRays(grid_scan, cp.max_range); });
  const PreparedScan prepared(cur, ScanForms{plicp, cp.resolution, cp.max_range});
  Prediction prediction;
  prediction.guess = guess;
  prediction.variance = prediction_variance;
  return searchAndChoose(submap, prepared, prediction, first, tp, plicp, cp);
}
}  // namespace

TEST(ScanMatcher, RecoversALargeUnpredictedMotion)
{
  const auto world = test::roomWorld();
  std::mt19937 rng(4);
  const CPose2D a(-4, 1, 0.3), motion(1.3, -0.7, 75 * M_PI / 180);
  const plicp::PlicpParams plicp;
  const plicp::ReferenceScan ref(scanAt(world, a, rng), plicp);
  const sensor::Scan cur = scanAt(world, a + motion, rng);
  const TrackingParams p;
  const CPose2D guess;  // zero motion: far from the truth
  const plicp::MatchResult first = plicp::matchScans(ref, cur, guess, plicp);
  ASSERT_TRUE(predictionFailed(first, guess, p));
  const auto s = searchAgainst(ref, ref.scan, cur, guess, first, p, plicp);
  ASSERT_TRUE(s.replaced);
  ASSERT_TRUE(s.match.ok());
  EXPECT_NEAR(s.match.pose.x(), motion.x(), 0.05);
  EXPECT_NEAR(s.match.pose.y(), motion.y(), 0.05);
  EXPECT_NEAR(std::remainder(s.match.pose.phi() - motion.phi(), 2 * M_PI), 0, 0.01);
  EXPECT_GE(s.compared.b, s.compared.a + p.min_score_gain);
  EXPECT_GE(s.searched_iterations, s.match.iterations);
}

TEST(ScanMatcher, ARightFirstMatchIsKept)
{
  const auto world = test::roomWorld();
  std::mt19937 rng(5);
  const CPose2D a(2, -2, -0.4), motion(0.4, 0.1, 0.2);
  const plicp::PlicpParams plicp;
  const plicp::ReferenceScan ref(scanAt(world, a, rng), plicp);
  const sensor::Scan cur = scanAt(world, a + motion, rng);
  const CPose2D guess = motion + CPose2D(0.15, -0.1, 0.05);
  const plicp::MatchResult first = plicp::matchScans(ref, cur, guess, plicp);
  ASSERT_TRUE(first.ok());
  const auto s = searchAgainst(ref, ref.scan, cur, guess, first, TrackingParams(), plicp);
  EXPECT_FALSE(s.replaced);
  EXPECT_EQ(s.match.pose, first.pose);
  EXPECT_NEAR(s.match.pose.x(), motion.x(), 0.03);
}

TEST(ScanMatcher, ARefinementThatLeavesTheSearchBasinIsRedoneWithinIt)
{
  // PLICP's keyframe disagrees with the score grid (here: the keyframe scan is taken 6 deg off
  // the pose the grid's scan was taken at), so PLICP from the search's pose ends where the grid
  // scores lower than the search's pose itself.
  const auto world = test::roomWorld();
  std::mt19937 rng(6);
  const CPose2D a(-3, 0.5, 0.2), motion(1.1, 0.4, 0.5);
  const plicp::PlicpParams plicp;
  const sensor::Scan grid_scan = scanAt(world, a, rng);
  const plicp::ReferenceScan ref(scanAt(world, a + CPose2D(0.1, 0, 6 * M_PI / 180), rng), plicp);
  const sensor::Scan cur = scanAt(world, a + motion, rng);
  TrackingParams p;
  const CPose2D guess;  // zero motion
  plicp::MatchResult failed;   // no first match: the searched one is kept if it converges
  const auto s = searchAgainst(ref, grid_scan, cur, guess, failed, p, plicp);
  ASSERT_TRUE(s.replaced);
  ASSERT_TRUE(s.bounded_refinement);
  EXPECT_GT(s.searched_iterations, s.match.iterations);  // both runs from the search's pose count

  // The same search without the second refinement keeps PLICP's pose, which scores lower.
  TrackingParams free = p;
  free.refine_correspondence_dist = 0;
  const auto f = searchAgainst(ref, grid_scan, cur, guess, failed, free, plicp);
  ASSERT_TRUE(f.replaced);
  EXPECT_FALSE(f.bounded_refinement);
  EXPECT_LT(f.searched_objective, f.search_objective);
  EXPECT_EQ(s.search_objective, f.search_objective);
  // Here the bounded refinement scores higher, and is kept.
  EXPECT_GT(s.searched_objective, f.searched_objective);
  EXPECT_NE(s.match.pose, f.match.pose);
}

// A corridor played backwards (the sensor moves away from what it faces): the scan sees wall
// beside it that the keyframe never saw. Compared on all points, a pose 1 m short pulls those
// points onto the keyframe's walls and wins, though the walls fix nothing along the corridor;
// compared on the points that can tell the two apart, the right match (on its prediction) is
// kept. (LocalTracker.ASingleWallIsWeakAlongItself has the converse: posts that one pose puts
// in unseen space still count for the other.)
TEST(ScanMatcher, PointsInUnseenSpaceDoNotChooseBetweenTwoMatches)
{
  const auto world = test::corridorWorld();
  const TrackingParams p;  // common_points_fraction 0.5
  correlative::CorrelativeParams cp;
  // Within 6 m the walls' hits are dense enough that the grid holds the walls, not the
  // keyframe's samples of them.
  cp.max_range = 6;
  // Off the keyframe's line and turned a little, so that no pose lays the scan's rays on the
  // keyframe's own (which would score higher for that alone).
  const CPose2D keyframe(0, 0, 0), truth(-1, 0.15, 0.04);  // in the keyframe's frame
  const Eigen::Vector3d right(truth.x(), truth.y(), truth.phi()), short_by_1m(0, 0.15, 0.04);
  for (unsigned seed = 1; seed <= 5; seed++)
  {
    std::mt19937 rng(seed);
    auto scan = [&](const CPose2D& pose) {
      return sensor::scanFromObservation(test::simulateObservation(world, pose, 361, M_PI, 30, 0.01, rng));
    };
    const sensor::Scan ref = scan(keyframe);
    const sensor::Scan cur = scan(truth);
    const ScorePyramid pyramid = correlative::searchPyramid(correlative::scanRays(ref, cp.max_range), cp);
    const auto points = correlative::thinPoints(cur.points, cp.resolution, cp.max_range);
    const SearchWindow w = correlative::searchWindow(cp, truth);  // the prediction is right
    const ScoreGrid& grid = pyramid.levels[0];

    const MatchComparison all =
        correlative::compareMatches(grid, points, w, right, short_by_1m, 0, p.surface_goes_on_ratio);
    EXPECT_EQ(all.common_points, 0u);
    // The bias: the short pose would win.
    EXPECT_GT(all.b, all.a + p.min_score_gain) << "seed " << seed;

    const MatchComparison common = correlative::compareMatches(grid, points, w, right, short_by_1m,
                                                               p.common_points_fraction, p.surface_goes_on_ratio);
    EXPECT_GE(common.common_points, p.common_points_fraction * points.size());
    EXPECT_LT(common.common_points, points.size());
    EXPECT_LT(common.b, common.a + p.min_score_gain) << "seed " << seed;  // the right match stays

    // Too few points in common (a fraction above theirs): compared on all points again.
    const double above = (common.common_points + 1.0) / points.size();
    const MatchComparison few =
        correlative::compareMatches(grid, points, w, right, short_by_1m, above, p.surface_goes_on_ratio);
    EXPECT_EQ(few.common_points, 0u);
    EXPECT_EQ(few.b, all.b);
    EXPECT_EQ(few.a, all.a);
  }
}

TEST(ScanMatcher, AlongACorridorThePredictionKeepsItsMatch)
{
  // The corridor of PointsInUnseenSpaceDoNotChooseBetweenTwoMatches, compared on all points:
  // there the grid scores a pose 1 m short, which pulls the scan back into what the keyframe
  // saw, above the right one. PLICP from the prediction (right) stays on it; the searched
  // match lies short of it along the corridor, where neither pair of scans fixes the motion.
  const auto world = test::corridorWorld();
  correlative::CorrelativeParams cp;
  cp.max_range = 6;
  TrackingParams p;
  p.common_points_fraction = 0;
  const plicp::PlicpParams plicp;
  const CPose2D truth(-1, 0.15, 0.04);
  for (unsigned seed = 1; seed <= 5; seed++)
  {
    std::mt19937 rng(seed);
    auto scan = [&](const CPose2D& pose) {
      return sensor::scanFromObservation(test::simulateObservation(world, pose, 361, M_PI, 30, 0.01, rng));
    };
    const plicp::ReferenceScan ref(scan(CPose2D()), plicp);
    const sensor::Scan cur = scan(truth);
    const plicp::MatchResult first = plicp::matchScans(ref, cur, truth, plicp);
    ASSERT_TRUE(first.ok());
    ASSERT_NEAR(first.pose.x(), truth.x(), 0.2) << "seed " << seed;  // nothing fixes x but noise

    TrackingParams objectives = p;
    objectives.prediction_decides_share = 0;
    const auto scored = searchAgainst(ref, ref.scan, cur, truth, first, objectives, plicp, cp);
    ASSERT_TRUE(scored.replaced) << "seed " << seed;
    EXPECT_GT(std::abs(scored.match.pose.x() - truth.x()), 0.5) << "seed " << seed;
    EXPECT_FALSE(scored.prediction_decided);

    // A prediction of unknown accuracy (as at a run's start) cannot choose either.
    const auto unknown = searchAgainst(ref, ref.scan, cur, truth, first, p, plicp, cp);
    EXPECT_FALSE(unknown.prediction_decided);
    EXPECT_EQ(unknown.match.pose, scored.match.pose);

    const double recent_errors = 0.1 * 0.1;
    const auto decided = searchAgainst(ref, ref.scan, cur, truth, first, p, plicp, cp, recent_errors);
    EXPECT_TRUE(decided.prediction_decided) << "seed " << seed;
    EXPECT_FALSE(decided.replaced);
    EXPECT_EQ(decided.match.pose, first.pose);
  }
}

TEST(ScanMatcher, AGuessIsSearchedFirstAMeasuredPredictionOnlyWhenItFails)
{
  const auto world = test::roomWorld();
  std::mt19937 rng(4);
  const CPose2D a(-4, 1, 0.3), motion(1.3, -0.7, 75 * M_PI / 180);
  const plicp::PlicpParams plicp;
  const correlative::CorrelativeParams cp;
  const TrackingParams tp;
  const auto ref = std::make_shared<const plicp::ReferenceScan>(scanAt(world, a, rng), plicp);
  const Submap submap(ref, [&] { return correlative::scanRays(ref->scan, cp.max_range); });
  const PreparedScan cur(scanAt(world, a + motion, rng), ScanForms{plicp, cp.resolution, cp.max_range});
  auto near = [&](const plicp::MatchResult& m) {
    return m.ok() && (m.pose.translation() - motion.translation()).norm() < 0.05 &&
           std::abs(std::remainder(m.pose.phi() - motion.phi(), 2 * M_PI)) < 0.01;
  };
  // No motion known: the guess (identity) is searched before any PLICP match, and the
  // search's match is kept.
  Prediction guess;
  const ScanMatch searched = ScanMatcher(tp, plicp, cp).match(submap, cur, guess);
  EXPECT_TRUE(searched.searched);
  EXPECT_TRUE(searched.replaced);
  EXPECT_TRUE(near(searched.match));
  EXPECT_GE(searched.iterations, searched.match.iterations);
  // The same guess measured (odometry said it): PLICP from it fails or moves it, which calls
  // for the search.
  guess.measured = true;
  EXPECT_TRUE(ScanMatcher(tp, plicp, cp).match(submap, cur, guess).searched);
  // The true motion, measured: its match confirms it, and nothing is searched.
  Prediction right;
  right.guess = motion;
  right.measured = true;
  const ScanMatch confirmed = ScanMatcher(tp, plicp, cp).match(submap, cur, right);
  EXPECT_FALSE(confirmed.searched);
  EXPECT_TRUE(near(confirmed.match));
  EXPECT_EQ(confirmed.iterations, confirmed.match.iterations);
  // Without the search, the guess's own PLICP match is all there is.
  correlative::CorrelativeParams off = cp;
  off.enabled = false;
  EXPECT_FALSE(ScanMatcher(tp, plicp, off).match(submap, cur, guess).searched);
}

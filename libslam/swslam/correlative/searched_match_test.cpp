// Re-alignment of a tracking match by the correlative search (tracking/searched_match.h).
#include <swslam/correlative/searched_match.h>

#include <Eigen/LU>
#include <Eigen/QR>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "test_support.h"

using namespace swslam;
using namespace swslam::correlative;
using mrpt::poses::CPose2D;

namespace
{
/** A CARMEN-like scan: 181 beams over 180 deg, 30 m. */
sensor::Scan scanAt(const test::World& world, const CPose2D& pose, std::mt19937& rng)
{
  return sensor::scanFromObservation(test::simulateObservation(world, pose, 181, M_PI, 30, 0.02, rng));
}

plicp::MatchResult converged(const CPose2D& pose, size_t inliers, size_t rays)
{
  plicp::MatchResult m;
  m.status = plicp::MatchStatus::Converged;
  m.pose = pose;
  m.inliers = inliers;
  m.cur_valid_rays = rays;
  return m;
}
bool predictionFailed(const plicp::MatchResult& m, const CPose2D& guess, const correlative::CorrelativeParams& p)
{
  return searchTrigger(m, guess, p) != SearchTrigger::None;
}
}  // namespace

TEST(SearchedMatch, PredictionFailsOnAFailedMatchFewInliersOrALargeCorrection)
{
  correlative::CorrelativeParams p;  // 0.1 m, 2 deg, half the points
  const CPose2D guess(1, 2, 0.5);
  EXPECT_FALSE(predictionFailed(converged(guess + CPose2D(0.05, 0.05, 0.02), 60, 100), guess, p));
  EXPECT_TRUE(predictionFailed(converged(guess, 49, 100), guess, p));
  EXPECT_TRUE(predictionFailed(converged(guess + CPose2D(0.0, 0.11, 0.0), 60, 100), guess, p));
  EXPECT_TRUE(predictionFailed(converged(guess + CPose2D(0, 0, 0.04), 60, 100), guess, p));
  plicp::MatchResult failed = converged(guess, 90, 100);
  failed.status = plicp::MatchStatus::TooFewCorrespondences;
  EXPECT_TRUE(predictionFailed(failed, guess, p));
  EXPECT_TRUE(predictionFailed(converged(guess, 0, 0), guess, p));
}

TEST(SearchedMatch, TheTriggerSaysWhy)
{
  correlative::CorrelativeParams p;
  const CPose2D guess(1, 2, 0.5);
  EXPECT_EQ(searchTrigger(converged(guess, 60, 100), guess, p), SearchTrigger::None);
  EXPECT_EQ(searchTrigger(converged(guess, 49, 100), guess, p), SearchTrigger::LowOverlap);
  // A match that moved its guess is "moved" whatever its overlap: only a match that stayed
  // near its guess can be trusted with little overlap (LocalTracker, trust_prediction_after).
  EXPECT_EQ(searchTrigger(converged(guess + CPose2D(0.2, 0, 0), 10, 100), guess, p), SearchTrigger::Moved);
  EXPECT_EQ(searchTrigger(converged(guess + CPose2D(0, 0, 0.04), 90, 100), guess, p), SearchTrigger::Moved);
  plicp::MatchResult failed = converged(guess, 90, 100);
  failed.status = plicp::MatchStatus::TooFewCorrespondences;
  EXPECT_EQ(searchTrigger(failed, guess, p), SearchTrigger::Failed);
}

TEST(SearchedMatch, AGuessIsAlwaysSearchedAMeasuredPredictionWhenItFailed)
{
  using T = SearchTrigger;
  for (const T why : {T::None, T::Failed, T::Moved, T::LowOverlap})
    for (const bool proven : {false, true})
    {
      const bool failed = why != T::None && !(why == T::LowOverlap && proven);
      EXPECT_TRUE(searchNeeded(why, false, true, proven)) << "a guess, searched";
      EXPECT_EQ(searchNeeded(why, false, false, proven), failed) << "a guess, searching guesses off";
      EXPECT_EQ(searchNeeded(why, true, true, proven), failed) << "a measured prediction";
      EXPECT_EQ(searchNeeded(why, true, false, proven), failed);
    }
  // Little overlap on a proven prediction (a door swung shut) is not searched; on an unproven
  // one, or a failed or moved match, it is.
  EXPECT_FALSE(searchNeeded(T::LowOverlap, true, true, true));
  EXPECT_TRUE(searchNeeded(T::LowOverlap, true, true, false));
  EXPECT_TRUE(searchNeeded(T::Moved, true, true, true));
  EXPECT_FALSE(searchNeeded(T::None, true, true, false));
}

TEST(SearchedMatch, AGuessIsSearchedBeforeAnyMatch)
{
  EXPECT_TRUE(searchFirst(false, true));
  EXPECT_FALSE(searchFirst(true, true));   // a measured prediction: PLICP first
  EXPECT_FALSE(searchFirst(false, false));  // guesses not searched: PLICP first
  // The not-run first match stands at the guess, fails, and so asks for the search.
  const plicp::MatchResult none = notRun(CPose2D(1, 2, 0.3));
  EXPECT_FALSE(none.ok());
  EXPECT_EQ(none.pose, CPose2D(1, 2, 0.3));
  EXPECT_EQ(searchTrigger(none, CPose2D(1, 2, 0.3), CorrelativeParams()), SearchTrigger::Failed);
  EXPECT_TRUE(searchNeeded(SearchTrigger::Failed, false, true, false));
}

TEST(SearchedMatch, AfterTheSearchTrackingKeepsTheFirstOnlyForOverlapAndLeavesFewInliersUnmatched)
{
  auto searched = [](bool replaced, size_t inliers) {
    SearchedMatch s;
    s.replaced = replaced;
    s.match.status = plicp::MatchStatus::Converged;
    s.match.cur_valid_rays = 100;
    s.match.inliers = inliers;
    return s;
  };
  using T = SearchTrigger;
  // A replacement of a first match searched for its little overlap needs 20 of 100 inliers.
  EXPECT_EQ(afterSearch(T::LowOverlap, searched(true, 19), 0.2, 0.1), AfterSearch::KeepFirst);
  EXPECT_EQ(afterSearch(T::LowOverlap, searched(true, 20), 0.2, 0.1), AfterSearch::Chosen);
  // Not for a first match that moved or failed, nor when the first match stayed.
  EXPECT_EQ(afterSearch(T::Moved, searched(true, 19), 0.2, 0.1), AfterSearch::Chosen);
  EXPECT_EQ(afterSearch(T::Failed, searched(true, 19), 0.2, 0.1), AfterSearch::Chosen);
  EXPECT_EQ(afterSearch(T::LowOverlap, searched(false, 19), 0.2, 0.1), AfterSearch::Chosen);
  // Under 10 of 100 inliers the chosen match, replaced or not, leaves the scan unmatched.
  for (const T why : {T::None, T::Failed, T::Moved})
    for (const bool replaced : {false, true})
    {
      EXPECT_EQ(afterSearch(why, searched(replaced, 9), 0.2, 0.1), AfterSearch::Unmatched);
      EXPECT_EQ(afterSearch(why, searched(replaced, 10), 0.2, 0.1), AfterSearch::Chosen);
    }
  EXPECT_EQ(afterSearch(T::LowOverlap, searched(false, 9), 0.2, 0.1), AfterSearch::Unmatched);
  // A failed match is no pose to keep or to call unmatched: the choice stands.
  SearchedMatch failed = searched(false, 0);
  failed.match.status = plicp::MatchStatus::TooFewCorrespondences;
  EXPECT_EQ(afterSearch(T::Failed, failed, 0.2, 0.1), AfterSearch::Chosen);
}

TEST(SearchedMatch, ScanRaysStartAtTheSensorAndStopAtMaxRange)
{
  sensor::Scan s;
  s.points = {{1, 0}, {0, 5}, {-3, 4}};
  const auto rays = scanRays(s, 4.5);
  ASSERT_EQ(rays.size(), 1u);
  EXPECT_EQ(rays[0].origin, Eigen::Vector2d::Zero());
  EXPECT_EQ(rays[0].hit, Eigen::Vector2d(1, 0));
  EXPECT_EQ(scanRays(s, 5.0).size(), 3u);
}

TEST(SearchedMatch, RecoversALargeUnpredictedMotion)
{
  const auto world = test::roomWorld();
  std::mt19937 rng(4);
  const CPose2D a(-4, 1, 0.3), motion(1.3, -0.7, 75 * M_PI / 180);
  const plicp::PlicpParams plicp;
  const plicp::ReferenceScan ref(scanAt(world, a, rng), plicp);
  const sensor::Scan cur = scanAt(world, a + motion, rng);
  const correlative::CorrelativeParams p;
  const CPose2D guess;  // zero motion: far from the truth
  const plicp::MatchResult first = plicp::matchScans(ref, cur, guess, plicp);
  ASSERT_TRUE(predictionFailed(first, guess, p));
  const auto s = searchAndMatch(ref, searchPyramid(scanRays(ref.scan, p.max_range), p), cur, guess, first, p, plicp);
  ASSERT_TRUE(s.replaced);
  ASSERT_TRUE(s.match.ok());
  EXPECT_NEAR(s.match.pose.x(), motion.x(), 0.05);
  EXPECT_NEAR(s.match.pose.y(), motion.y(), 0.05);
  EXPECT_NEAR(std::remainder(s.match.pose.phi() - motion.phi(), 2 * M_PI), 0, 0.01);
  EXPECT_GE(s.compared.searched, s.compared.first + p.min_score_gain);
  EXPECT_GE(s.searched_iterations, s.match.iterations);
}

TEST(SearchedMatch, ARightFirstMatchIsKept)
{
  const auto world = test::roomWorld();
  std::mt19937 rng(5);
  const CPose2D a(2, -2, -0.4), motion(0.4, 0.1, 0.2);
  const plicp::PlicpParams plicp;
  const plicp::ReferenceScan ref(scanAt(world, a, rng), plicp);
  const sensor::Scan cur = scanAt(world, a + motion, rng);
  const correlative::CorrelativeParams p;
  const CPose2D guess = motion + CPose2D(0.15, -0.1, 0.05);
  const plicp::MatchResult first = plicp::matchScans(ref, cur, guess, plicp);
  ASSERT_TRUE(first.ok());
  const auto s = searchAndMatch(ref, searchPyramid(scanRays(ref.scan, p.max_range), p), cur, guess, first, p, plicp);
  EXPECT_FALSE(s.replaced);
  EXPECT_EQ(s.match.pose, first.pose);
  EXPECT_NEAR(s.match.pose.x(), motion.x(), 0.03);
}

TEST(SearchedMatch, ARefinementThatLeavesTheSearchBasinIsRedoneWithinIt)
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
  correlative::CorrelativeParams p;
  const auto pyramid = searchPyramid(scanRays(grid_scan, p.max_range), p);
  const CPose2D guess;  // zero motion
  plicp::MatchResult failed;   // no first match: the searched one is kept if it converges
  const auto s = searchAndMatch(ref, pyramid, cur, guess, failed, p, plicp);
  ASSERT_TRUE(s.replaced);
  ASSERT_TRUE(s.bounded_refinement);
  EXPECT_GT(s.searched_iterations, s.match.iterations);  // both runs from the search's pose count

  // The same search without the second refinement keeps PLICP's pose, which scores lower.
  correlative::CorrelativeParams free = p;
  free.refine_correspondence_dist = 0;
  const auto f = searchAndMatch(ref, pyramid, cur, guess, failed, free, plicp);
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
TEST(SearchedMatch, PointsInUnseenSpaceDoNotChooseBetweenTwoMatches)
{
  const auto world = test::corridorWorld();
  correlative::CorrelativeParams p;  // common_points_fraction 0.5
  // Within 6 m the walls' hits are dense enough that the grid holds the walls, not the
  // keyframe's samples of them.
  p.max_range = 6;
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
    const ScorePyramid pyramid = searchPyramid(scanRays(ref, p.max_range), p);
    const auto points = thinPoints(cur.points, p.resolution, p.max_range);
    const SearchWindow w = searchWindow(p, truth);  // the prediction is right
    const ScoreGrid& grid = pyramid.levels[0];

    const MatchComparison all = compareMatches(grid, points, w, right, short_by_1m, 0, p.surface_goes_on_ratio);
    EXPECT_EQ(all.common_points, 0u);
    // The bias: the short pose would win.
    EXPECT_GT(all.searched, all.first + p.min_score_gain) << "seed " << seed;

    const MatchComparison common = compareMatches(grid, points, w, right, short_by_1m, p.common_points_fraction,
                                                  p.surface_goes_on_ratio);
    EXPECT_GE(common.common_points, p.common_points_fraction * points.size());
    EXPECT_LT(common.common_points, points.size());
    EXPECT_LT(common.searched, common.first + p.min_score_gain) << "seed " << seed;  // the right match stays

    // Too few points in common (a fraction above theirs): compared on all points again.
    const double above = (common.common_points + 1.0) / points.size();
    const MatchComparison few = compareMatches(grid, points, w, right, short_by_1m, above, p.surface_goes_on_ratio);
    EXPECT_EQ(few.common_points, 0u);
    EXPECT_EQ(few.searched, all.searched);
    EXPECT_EQ(few.first, all.first);
  }
}

namespace
{
/** informationShare the slow way: the information matrix inverted explicitly, its largest
 * eigenvalue by power iteration. */
double informationShareByPowerIteration(const Eigen::Matrix3d& cov, const Eigen::Vector3d& d, double length)
{
  const Eigen::DiagonalMatrix<double, 3> S(1, 1, length);
  const Eigen::Matrix3d scaled = S * cov * S;
  const Eigen::Matrix3d info = scaled.inverse();
  Eigen::Vector3d v(1, 0.7, 0.3);
  for (int i = 0; i < 2000; i++) v = (info * v).normalized();
  const double largest = v.dot(info * v);
  const Eigen::Vector3d u = (S * d).normalized();
  return u.dot(info * u) / largest;
}
}  // namespace

TEST(SearchedMatch, InformationShareAgreesWithPowerIteration)
{
  std::mt19937 rng(11);
  std::normal_distribution<double> N(0, 1);
  std::uniform_real_distribution<double> U(0.5, 20);
  for (int trial = 0; trial < 200; trial++)
  {
    Eigen::Matrix3d A;
    for (int i = 0; i < 9; i++) A(i / 3, i % 3) = N(rng);
    // Variances spread over six decades, as a corridor's match has them.
    const Eigen::Vector3d spread(std::pow(10.0, -3 + 3 * U(rng) / 20), std::pow(10.0, -6 + 6 * U(rng) / 20), 1e-4);
    const Eigen::Matrix3d Q = Eigen::HouseholderQR<Eigen::Matrix3d>(A).householderQ();
    const Eigen::Matrix3d cov = Q * spread.asDiagonal() * Q.transpose();
    const Eigen::Vector3d d(N(rng), N(rng), 0.1 * N(rng));
    const double length = U(rng);
    const double share = informationShare(cov, d, length);
    EXPECT_GE(share, 0);
    EXPECT_LE(share, 1);
    EXPECT_NEAR(share, informationShareByPowerIteration(cov, d, length), 1e-6 * std::max(share, 1e-3))
        << "trial " << trial;
  }
  // Along the strongest direction the share is 1, along a pure eigendirection its ratio.
  const Eigen::Matrix3d corridor = Eigen::Vector3d(4.0, 1e-4, 1e-6).asDiagonal();
  EXPECT_NEAR(informationShare(corridor, Eigen::Vector3d(0, 0, 1), 1.0), 1.0, 1e-12);
  EXPECT_NEAR(informationShare(corridor, Eigen::Vector3d(1, 0, 0), 1.0), 1e-6 / 4.0, 1e-15);
  EXPECT_NEAR(informationShare(corridor, Eigen::Vector3d(0, 1, 0), 1.0), 1e-2, 1e-12);
  // The length scales a turn: heading variance 1e-6 rad^2 at 10 m is 1e-4 m^2, as y's.
  EXPECT_NEAR(informationShare(corridor, Eigen::Vector3d(0, 1, 0), 10.0), 1.0, 1e-12);
}

TEST(SearchedMatch, InformationShareIsOneWhereNothingCanBeSaid)
{
  const Eigen::Matrix3d cov = Eigen::Vector3d(4.0, 1e-4, 1e-6).asDiagonal();
  const Eigen::Vector3d along(1, 0, 0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(informationShare(cov, Eigen::Vector3d::Zero(), 1.0), 1.0) << "no difference";
  EXPECT_EQ(informationShare(cov, Eigen::Vector3d(nan, 0, 0), 1.0), 1.0);
  EXPECT_EQ(informationShare(cov, along, 0.0), 1.0) << "no length";
  EXPECT_EQ(informationShare(cov, along, nan), 1.0);
  EXPECT_EQ(informationShare(Eigen::Matrix3d::Zero(), along, 1.0), 1.0) << "no covariance";
  EXPECT_EQ(informationShare(Eigen::Vector3d(4.0, -1e-4, 1e-6).asDiagonal(), along, 1.0), 1.0) << "not positive";
  Eigen::Matrix3d bad = cov;
  bad(0, 1) = bad(1, 0) = nan;
  EXPECT_EQ(informationShare(bad, along, 1.0), 1.0) << "not finite";
}

TEST(SearchedMatch, ThePredictionChoosesWhereTheScansCannot)
{
  // A match along a corridor (x): 2 m of standard deviation along it, a centimetre across,
  // a milliradian in heading.
  const Eigen::Matrix3d cov = Eigen::Vector3d(4.0, 1e-4, 1e-6).asDiagonal();
  const Eigen::Vector3d prediction(1.0, 0.0, 0.0), at(1.02, 0.01, 0.001), short_by_1m(0.0, 0.01, 0.001);
  const double share = 1e-3, length = 5;
  const double known = 0.05 * 0.05;  // the prediction's recent errors: 5 cm
  EXPECT_EQ(predictionChoice(at, short_by_1m, prediction, cov, length, share, known), PredictionChoice::First);
  EXPECT_EQ(predictionChoice(short_by_1m, at, prediction, cov, length, share, known), PredictionChoice::Searched);
  EXPECT_EQ(predictionChoice(at, short_by_1m, prediction, cov, length, 0, known), PredictionChoice::Scans) << "off";
  // A prediction no better than the two matches are apart tells nothing either: 1 m apart,
  // with errors of 0.34 m it cannot tell them (3 sigma), with 0.33 m it can.
  EXPECT_EQ(predictionChoice(at, short_by_1m, prediction, cov, length, share, 0.34 * 0.34), PredictionChoice::Scans);
  EXPECT_EQ(predictionChoice(at, short_by_1m, prediction, cov, length, share, 0.33 * 0.33), PredictionChoice::First);
  const double unknown = std::numeric_limits<double>::infinity();
  EXPECT_EQ(predictionChoice(at, short_by_1m, prediction, cov, length, share, unknown), PredictionChoice::Scans);
  // Across the corridor the match is informed: the objectives choose.
  const Eigen::Vector3d aside(1.02, 0.5, 0.001);
  EXPECT_EQ(predictionChoice(at, aside, prediction, cov, length, share, known), PredictionChoice::Scans);
  // Equally far from the prediction: the first stays.
  const Eigen::Vector3d ahead(1.5, 0.01, 0.001), behind(0.5, 0.01, 0.001);
  EXPECT_EQ(predictionChoice(ahead, behind, prediction, cov, length, share, known), PredictionChoice::First);
  // Headings are compared wrapped: a searched match across +-pi from the first, along a weak
  // heading, is a small difference, not a full turn.
  const Eigen::Matrix3d weak_heading = Eigen::Vector3d(1e-4, 1e-4, 1.0).asDiagonal();
  const Eigen::Vector3d near_pi(0, 0, M_PI - 0.01), across(0, 0, -M_PI + 0.02), pred_pi(0, 0, M_PI);
  EXPECT_EQ(predictionChoice(near_pi, across, pred_pi, weak_heading, 1.0, share, 1e-6), PredictionChoice::First);
  EXPECT_EQ(predictionChoice(across, near_pi, pred_pi, weak_heading, 1.0, share, 1e-6), PredictionChoice::Searched);
}

TEST(SearchedMatch, AlongACorridorThePredictionKeepsItsMatch)
{
  // The corridor of PointsInUnseenSpaceDoNotChooseBetweenTwoMatches, compared on all points:
  // there the grid scores a pose 1 m short, which pulls the scan back into what the keyframe
  // saw, above the right one. PLICP from the prediction (right) stays on it; the searched
  // match lies short of it along the corridor, where neither pair of scans fixes the motion.
  const auto world = test::corridorWorld();
  correlative::CorrelativeParams p;
  p.max_range = 6;
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
    const ScorePyramid pyramid = searchPyramid(scanRays(ref.scan, p.max_range), p);
    const plicp::MatchResult first = plicp::matchScans(ref, cur, truth, plicp);
    ASSERT_TRUE(first.ok());
    ASSERT_NEAR(first.pose.x(), truth.x(), 0.2) << "seed " << seed;  // nothing fixes x but noise

    correlative::CorrelativeParams objectives = p;
    objectives.prediction_decides_share = 0;
    const auto scored = searchAndMatch(ref, pyramid, cur, truth, first, objectives, plicp);
    ASSERT_TRUE(scored.replaced) << "seed " << seed;
    EXPECT_GT(std::abs(scored.match.pose.x() - truth.x()), 0.5) << "seed " << seed;
    EXPECT_FALSE(scored.prediction_decided);

    // A prediction of unknown accuracy (as at a run's start) cannot choose either.
    const auto unknown = searchAndMatch(ref, pyramid, cur, truth, first, p, plicp);
    EXPECT_FALSE(unknown.prediction_decided);
    EXPECT_EQ(unknown.match.pose, scored.match.pose);

    const double recent_errors = 0.1 * 0.1;
    const auto decided = searchAndMatch(ref, pyramid, cur, truth, first, p, plicp, 0, recent_errors);
    EXPECT_TRUE(decided.prediction_decided) << "seed " << seed;
    EXPECT_FALSE(decided.replaced);
    EXPECT_EQ(decided.match.pose, first.pose);
  }
}

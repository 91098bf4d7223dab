// Tracking's rules around the correlative search (search_policy.h).
#include <swslam/tracking/search_policy.h>

#include <Eigen/LU>
#include <Eigen/QR>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace swslam;
using namespace swslam::tracking;
using mrpt::poses::CPose2D;

namespace
{
plicp::MatchResult converged(const CPose2D& pose, size_t inliers, size_t rays)
{
  plicp::MatchResult m;
  m.status = plicp::MatchStatus::Converged;
  m.pose = pose;
  m.inliers = inliers;
  m.cur_valid_rays = rays;
  return m;
}
bool predictionFailed(const plicp::MatchResult& m, const CPose2D& guess, const TrackingParams& p)
{
  return searchTrigger(m, guess, p) != SearchTrigger::None;
}
}  // namespace

TEST(SearchPolicy, PredictionFailsOnAFailedMatchFewInliersOrALargeCorrection)
{
  TrackingParams p;  // 0.1 m, 2 deg, half the points
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

TEST(SearchPolicy, TheTriggerSaysWhy)
{
  TrackingParams p;
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

TEST(SearchPolicy, AGuessIsAlwaysSearchedAMeasuredPredictionWhenItFailed)
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

TEST(SearchPolicy, AGuessIsSearchedBeforeAnyMatch)
{
  EXPECT_TRUE(searchFirst(false, true));
  EXPECT_FALSE(searchFirst(true, true));   // a measured prediction: PLICP first
  EXPECT_FALSE(searchFirst(false, false));  // guesses not searched: PLICP first
  // The not-run first match stands at the guess, fails, and so asks for the search.
  const plicp::MatchResult none = notRun(CPose2D(1, 2, 0.3));
  EXPECT_FALSE(none.ok());
  EXPECT_EQ(none.pose, CPose2D(1, 2, 0.3));
  EXPECT_EQ(searchTrigger(none, CPose2D(1, 2, 0.3), TrackingParams()), SearchTrigger::Failed);
  EXPECT_TRUE(searchNeeded(SearchTrigger::Failed, false, true, false));
}

TEST(SearchPolicy, AfterTheSearchTrackingKeepsTheFirstOnlyForOverlapAndLeavesFewInliersUnmatched)
{
  auto chosen = [](size_t inliers) {
    plicp::MatchResult m;
    m.status = plicp::MatchStatus::Converged;
    m.cur_valid_rays = 100;
    m.inliers = inliers;
    return m;
  };
  const TrackingParams p;  // overlap_search_min_inlier_fraction 0.2, searched_min_inlier_fraction 0.1
  using T = SearchTrigger;
  // A replacement of a first match searched for its little overlap needs 20 of 100 inliers.
  EXPECT_EQ(afterSearch(T::LowOverlap, chosen(19), true, p), AfterSearch::KeepFirst);
  EXPECT_EQ(afterSearch(T::LowOverlap, chosen(20), true, p), AfterSearch::Chosen);
  // Not for a first match that moved or failed, nor when the first match stayed.
  EXPECT_EQ(afterSearch(T::Moved, chosen(19), true, p), AfterSearch::Chosen);
  EXPECT_EQ(afterSearch(T::Failed, chosen(19), true, p), AfterSearch::Chosen);
  EXPECT_EQ(afterSearch(T::LowOverlap, chosen(19), false, p), AfterSearch::Chosen);
  // Under 10 of 100 inliers the chosen match, replaced or not, leaves the scan unmatched.
  for (const T why : {T::None, T::Failed, T::Moved})
    for (const bool replaced : {false, true})
    {
      EXPECT_EQ(afterSearch(why, chosen(9), replaced, p), AfterSearch::Unmatched);
      EXPECT_EQ(afterSearch(why, chosen(10), replaced, p), AfterSearch::Chosen);
    }
  EXPECT_EQ(afterSearch(T::LowOverlap, chosen(9), false, p), AfterSearch::Unmatched);
  // A failed match is no pose to keep or to call unmatched: the choice stands.
  plicp::MatchResult failed = chosen(0);
  failed.status = plicp::MatchStatus::TooFewCorrespondences;
  EXPECT_EQ(afterSearch(T::Failed, failed, false, p), AfterSearch::Chosen);
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

TEST(SearchPolicy, InformationShareAgreesWithPowerIteration)
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

TEST(SearchPolicy, InformationShareIsOneWhereNothingCanBeSaid)
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

TEST(SearchPolicy, ThePredictionChoosesWhereTheScansCannot)
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


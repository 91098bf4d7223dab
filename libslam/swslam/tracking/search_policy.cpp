#include <swslam/tracking/search_policy.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace swslam::tracking
{
using mrpt::poses::CPose2D;

SearchTrigger searchTrigger(const plicp::MatchResult& m, const CPose2D& guess, const TrackingParams& p)
{
  if (!m.ok() || m.cur_valid_rays == 0) return SearchTrigger::Failed;
  if ((m.pose.translation() - guess.translation()).norm() > p.trigger_correction_xy ||
      std::abs(std::remainder(m.pose.phi() - guess.phi(), 2 * M_PI)) > p.trigger_correction_theta)
    return SearchTrigger::Moved;
  if (m.inliers < p.trigger_inlier_fraction * m.cur_valid_rays) return SearchTrigger::LowOverlap;
  return SearchTrigger::None;
}

bool searchNeeded(SearchTrigger why, bool guess_measured, bool search_guesses, bool proven)
{
  if (search_guesses && !guess_measured) return true;
  return why != SearchTrigger::None && !(why == SearchTrigger::LowOverlap && proven);
}

bool searchFirst(bool guess_measured, bool search_guesses) { return search_guesses && !guess_measured; }

plicp::MatchResult notRun(const CPose2D& guess)
{
  plicp::MatchResult m;
  m.status = plicp::MatchStatus::InvalidInput;
  m.pose = guess;
  m.message = "not run: the guess was searched first";
  return m;
}

AfterSearch afterSearch(SearchTrigger why, const plicp::MatchResult& chosen, bool replaced, const TrackingParams& p)
{
  if (replaced && why == SearchTrigger::LowOverlap && chosen.ok() &&
      chosen.inliers < p.overlap_search_min_inlier_fraction * chosen.cur_valid_rays)
    return AfterSearch::KeepFirst;
  if (chosen.ok() && chosen.inliers < p.searched_min_inlier_fraction * chosen.cur_valid_rays)
    return AfterSearch::Unmatched;
  return AfterSearch::Chosen;
}

double informationShare(const Eigen::Matrix3d& covariance, const Eigen::Vector3d& difference, double length)
{
  if (!(length > 0) || !std::isfinite(length) || !difference.allFinite() || !covariance.allFinite()) return 1.0;
  const Eigen::DiagonalMatrix<double, 3> S(1, 1, length);
  Eigen::Vector3d u = S * difference;
  if (!(u.norm() > 0)) return 1.0;
  u.normalize();
  // The information is the inverse of the covariance: its eigenvalues are the inverses of the
  // covariance's, so no inverse is formed (a near-singular direction is the strongest).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(S * covariance * S);
  if (es.info() != Eigen::Success) return 1.0;
  const Eigen::Vector3d variances = es.eigenvalues();
  if (!(variances.minCoeff() > 0)) return 1.0;
  const Eigen::Vector3d along = es.eigenvectors().transpose() * u;
  double information = 0;
  for (int k = 0; k < 3; k++) information += along(k) * along(k) / variances(k);
  return std::clamp(information * variances.minCoeff(), 0.0, 1.0);
}

PredictionChoice predictionChoice(const Eigen::Vector3d& first, const Eigen::Vector3d& searched,
                                  const Eigen::Vector3d& prediction, const Eigen::Matrix3d& searched_covariance,
                                  double length, double share, double prediction_variance)
{
  auto wrapped = [](Eigen::Vector3d d) {
    d.z() = std::remainder(d.z(), 2 * M_PI);
    return d;
  };
  const Eigen::Vector3d d = wrapped(searched - first);
  if (!(share > 0) || !(informationShare(searched_covariance, d, length) < share)) return PredictionChoice::Scans;
  // informationShare accepted the length and the difference: both are finite, and d is not 0.
  const Eigen::DiagonalMatrix<double, 3> S(1, 1, length);
  const Eigen::Vector3d apart = S * d;
  if (!(apart.squaredNorm() > kPredictionSigmas * kPredictionSigmas * prediction_variance))
    return PredictionChoice::Scans;
  const Eigen::Vector3d u = apart.normalized();
  const double first_off = std::abs(u.dot(S * wrapped(first - prediction)));
  const double searched_off = std::abs(u.dot(S * wrapped(searched - prediction)));
  return first_off <= searched_off ? PredictionChoice::First : PredictionChoice::Searched;
}

}  // namespace swslam::tracking

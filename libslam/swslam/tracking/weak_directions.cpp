#include <swslam/tracking/weak_directions.h>

#include <algorithm>

namespace swslam::tracking
{
WeakDirections takePriorWhereWeak(plicp::MatchResult& m, const Keyframe& ref, const PreparedScan& cur,
                                  const mrpt::poses::CPose2D& prior, double prior_var_xy, const TrackingParams& p,
                                  const plicp::PlicpParams& plicp)
{
  if (!m.ok() || p.ambiguity_factor <= 0) return {};
  const double length = cur.rotationLength();
  const double noise = residualNoiseVariance(m.sum_sq_residuals, m.correspondences, plicp.range_sigma * plicp.range_sigma);
  const double threshold = weakRatioThreshold(noise, plicp.min_segment_length, p.ambiguity_factor);
  const Ambiguity a = findWeakDirections(m.covariance, length, threshold);
  // Along a direction no surface faces, the match moved by noise alone (a single wall lets the
  // scans slide along it by metres): the prediction decides there. The match's two weaker
  // directions are candidates whatever their information says: a wall's line can look
  // informed by the noise of one scan (about one in ten on a simulated wall).
  Ambiguity taken = a;
  taken.weak = 0;
  const Ambiguity candidates = findWeakDirections(m.covariance, length, 1.0);
  if (p.unobservable_min_rays > 0 && candidates.ratio < kFacingCheckRatio * threshold)
    taken = unobservableDirections(candidates, {ref.scan->scan.points, *ref.facing, 0.0},
                                   {cur.scan().points, *cur.facing(), m.pose.phi()}, length, p.unobservable_min_rays);
  if (taken.weak == 0) return {a.weak, 0};
  const double sth = p.lost_prior_sigma_theta;
  Eigen::Vector3d x(m.pose.x(), m.pose.y(), m.pose.phi());
  takePriorAlongWeak(x, m.covariance, Eigen::Vector3d(prior.x(), prior.y(), prior.phi()),
                     Eigen::Vector3d(prior_var_xy, prior_var_xy, sth * sth).asDiagonal(), taken, length);
  m.pose = mrpt::poses::CPose2D(x.x(), x.y(), x.z());
  return {std::max(a.weak, taken.weak), taken.weak};
}

}  // namespace swslam::tracking

#include <swslam/tracking/placement.h>

#include <swslam/geometry/se2_error.h>
#include <swslam/geometry/se2_scaling.h>

#include <Eigen/Cholesky>

#include <algorithm>

namespace swslam::tracking
{
using mrpt::poses::CPose2D;

CPose2D placeBetweenKeyframes(const CPose2D& b_from_a, double t, double interval, const CPose2D& match,
                              const Eigen::Matrix3d& information, const PlacementModel& model)
{
  if (!(interval > 0) || !(t > 0) || !(t < interval)) return match;
  const CPose2D interpolated = geometry::scaledMotion(b_from_a, t / interval);
  // Constant acceleration a over the interval moves a point at t by a t (T - t) / 2 off the
  // straight interpolation; its square is the prior's variance (floored: never singular).
  const double spread = 0.5 * t * (interval - t);
  const double sxy = std::max(model.acceleration * spread, 1e-6);
  const double sth = std::max(model.angular_acceleration * spread, 1e-6);
  const Eigen::Matrix3d prior = Eigen::Vector3d(1 / (sxy * sxy), 1 / (sxy * sxy), 1 / (sth * sth)).asDiagonal();
  const Eigen::Vector3d offset(match.x() - interpolated.x(), match.y() - interpolated.y(),
                               geometry::wrapAngle(match.phi() - interpolated.phi()));
  // A match whose information is not finite tells nothing: the interpolation alone.
  if (!information.allFinite()) return interpolated;
  const Eigen::Vector3d step = (information + prior).ldlt().solve(information * offset);
  return CPose2D(interpolated.x() + step.x(), interpolated.y() + step.y(),
                 geometry::wrapAngle(interpolated.phi() + step.z()));
}

}  // namespace swslam::tracking

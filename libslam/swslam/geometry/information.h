#pragma once
// The information matrix (inverse covariance) of a measurement, as graph edges carry it.

#include <Eigen/Core>

namespace swslam::geometry
{
/** Information matrix of a covariance, with variances floored at `min_variance` so that a
 * near-singular covariance gives a large but finite information. */
Eigen::Matrix3d informationFromCovariance(const Eigen::Matrix3d& cov, double min_variance = 1e-9);

}  // namespace swslam::geometry

#pragma once
// Ambiguous matches (doc/tracking.md, "Ambiguous matches"): the directions of a scan match that
// the scans do not constrain (a corridor's axis, the line of a single wall, open water), found
// from the eigen-decomposition of the match's information in a unit-consistent form, and the
// motion prior taken along them with the prior's own, large, variance.

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace swslam::tracking
{
/** The weak directions of a match. Directions are unit vectors in normalized coordinates
 * u = [x, y, length * theta] (metres: a turn by theta moves a point `length` away by
 * length * theta), so that translation and rotation compare. */
struct Ambiguity
{
  int weak = 0;                 ///< number of weak directions (0: the match is well constrained)
  Eigen::Matrix3d directions = Eigen::Matrix3d::Zero();  ///< its first `weak` columns
  double ratio = 1;             ///< weakest / strongest information (normalized)
  double threshold = 0;         ///< ratio below which a direction is weak
};

/** The information ratio below which a direction is weak: `factor` times what noise alone
 * fakes along a featureless direction. A point-to-line term informs the direction of its
 * segment's normal; noise of variance sigma^2 at both ends of a segment of length l tilts that
 * normal by about sqrt(2) sigma / l, so a featureless direction still receives
 * tilt^2 = 2 sigma^2 / l^2 of a point's information. sigma^2 is the noise the match's
 * residuals show (sum of squared residuals / (n - 3)), or the datasheet's range_sigma^2 when
 * n <= 3. Clamped to [0, 0.5]: at most, a direction with half the strongest's information is
 * weak. 0 when an input is not positive and finite (no direction is weak). */
double weakRatioThreshold(double noise_variance, double min_segment_length, double factor);

/** The noise variance a match's residuals show: sum_sq_residuals / (n - 3), three parameters
 * fitted to n point-to-line residuals; `fallback` when n <= 3. */
double residualNoiseVariance(double sum_sq_residuals, size_t n, double fallback);

/** Root mean square distance of the points from the sensor [m], the length that scales
 * rotations to metres; 1 m when there are none (or all sit at the sensor). */
double rotationLength(const std::vector<Eigen::Vector2d>& points);

/** Weak directions of a match of covariance `cov` over [x, y, theta]: the eigenvectors of the
 * normalized information S^-1 cov^-1 S^-1, S = diag(1, 1, length), whose eigenvalue is below
 * `threshold` times the largest. The decomposition is of the normalized covariance (the same
 * eigenvectors, reciprocal eigenvalues), so a singular information needs no inverse. A
 * covariance that is not finite, or not positive definite, has every direction weak. */
Ambiguity findWeakDirections(const Eigen::Matrix3d& cov, double length, double threshold);

/** Takes the prior along the weak directions, where the match's information is no more than
 * noise fakes: along each weak direction v (normalized coordinates) the pose's component
 * becomes the prior's (angles wrapped) and its variance the prior's variance along v; across
 * the weak directions nothing changes, and nothing at all when a.weak == 0. A covariance
 * that is not finite gives the prior and its covariance. */
void takePriorAlongWeak(Eigen::Vector3d& pose, Eigen::Matrix3d& cov, const Eigen::Vector3d& prior,
                        const Eigen::Matrix3d& prior_cov, const Ambiguity& a, double length);

}  // namespace swslam::tracking

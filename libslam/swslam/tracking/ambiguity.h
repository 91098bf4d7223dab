#pragma once
// Ambiguous matches (doc/tracking.md, "Ambiguous matches"): the directions of a scan match that
// the scans do not constrain (a corridor's axis, the line of a single wall, open water), found
// from the eigen-decomposition of the match's information in a unit-consistent form, and the
// motion prior taken along them with the prior's own, large, variance.

#include <Eigen/Core>

#include <cstddef>
#include <limits>
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

/** Weak directions of a match of covariance `cov` over [x, y, theta]: the eigenvectors of the
 * normalized information S^-1 cov^-1 S^-1, S = diag(1, 1, length), whose eigenvalue is below
 * `threshold` times the largest. The decomposition is of the normalized covariance (the same
 * eigenvectors, reciprocal eigenvalues), so a singular information needs no inverse. A
 * covariance that is not finite, or not positive definite, has every direction weak. */
Ambiguity findWeakDirections(const Eigen::Matrix3d& cov, double length, double threshold);

/** Per unit step along a normalized direction v, the change of the point-to-line residual of
 * a point q with segment normal n: |[n, n . perp(q) / length] . v|, perp(q) = (-q_y, q_x).
 * A ray whose sensitivity reaches this is evidence along v: range noise tilts the normal of
 * a featureless wall's segments by about sqrt(2) sigma / min_segment_length (0.07 with 1 cm
 * noise and 20 cm segments), a surface facing v (a door's jamb, a pillar, a corner) by far
 * more. */
constexpr double kFacingSensitivity = 0.3;

/** A match is tested for unobservable directions only if its weakest direction has less than
 * this many times the weak threshold's information (weakRatioThreshold): noise made a
 * simulated wall's line look up to 6 times above it in single scans, a room's weakest
 * direction has 7 to 100 times. */
constexpr double kFacingCheckRatio = 10.0;

/** The facing test's surface normals: per point, the unit normals (turned +90 deg from the
 * chord) of the chords to the first point at least `min_segment` away on either side, walking
 * at most kFacingMaxWalk rays through consecutive points no farther than
 * kFacingMaxSegmentFactor * min_segment apart, the chord itself no longer than that; a zero
 * vector where there is none. A shorter chord has a normal that noise tilts by more than
 * sqrt(2) sigma / min_segment; a longer one, or one across a gap, joins two surfaces (the far
 * ends of a corridor's two walls across the rays that reach neither), and its normal tells
 * nothing of either. A door's jamb or recess is walked within a few decimetres. */
struct FacingNormals
{
  std::vector<Eigen::Vector2d> lo, hi;
};
constexpr double kFacingMaxSegmentFactor = 3.0;
constexpr int kFacingMaxWalk = 64;
FacingNormals facingNormals(const std::vector<Eigen::Vector2d>& points, double min_segment);

/** A scan's points and their FacingNormals, in its sensor's frame, which is turned by
 * `heading` from the frame the directions are given in. */
struct FacingView
{
  const std::vector<Eigen::Vector2d>& points;
  const FacingNormals& normals;
  double heading = 0;
};

/** How many of the scan's points face the normalized direction `v`, counted up to `enough`: a
 * point counts when the sensitivity of either of its normals reaches kFacingSensitivity. 0
 * when the vectors differ in size or length is not positive. */
size_t raysFacing(const FacingView& scan, const Eigen::Vector3d& v, double length,
                  size_t enough = std::numeric_limits<size_t>::max());

/** The weak directions of `a` that fewer than `min_rays` points of either scan face
 * (raysFacing; the two scans of a match: where only one of them sees a surface facing a
 * direction, their overlap does not): directions no surface informs, as a single wall's own
 * line, unlike a corridor whose doors and recesses inform its axis, if weakly. None when
 * min_rays is 0. */
Ambiguity unobservableDirections(const Ambiguity& a, const FacingView& reference, const FacingView& current,
                                 double length, int min_rays);

/** Takes the prior along the weak directions, where the match's information is no more than
 * noise fakes: along each weak direction v (normalized coordinates) the pose's component
 * becomes the prior's (angles wrapped) and its variance the prior's variance along v; across
 * the weak directions nothing changes, and nothing at all when a.weak == 0. A covariance
 * that is not finite gives the prior and its covariance. */
void takePriorAlongWeak(Eigen::Vector3d& pose, Eigen::Matrix3d& cov, const Eigen::Vector3d& prior,
                        const Eigen::Matrix3d& prior_cov, const Ambiguity& a, double length);

}  // namespace swslam::tracking

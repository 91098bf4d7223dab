#pragma once
// Closed-form covariance of the PLICP estimate (paper eq. 4-10, after Censi 2007):
//   cov(x) = H^-1 (dJ2/dxdz) cov(z) (dJ2/dxdz)' H^-1,  H = d2J/dx2,
// with z the measured ranges of the rays used by the correspondences.

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace swslam::plicp
{
/** One correspondence in polar form: ray directions (unit vectors) and ranges. Rays are
 * identified by their index so that a ray used by several correspondences is one
 * measurement (one column of d2J/dxdz), not several independent ones. */
struct CovarianceTerm
{
  Eigen::Vector2d dir_i, dir_j1, dir_j2;  ///< unit ray directions (theta_i, theta_j1, theta_j2)
  double rho_i = 0, rho_j1 = 0, rho_j2 = 0;
  int ray_i = -1, ray_j1 = -1, ray_j2 = -1;  ///< current / reference valid-ray indices
};

/** Second derivatives of J_i for one term at x = [tx, ty, th]: H_i (eq. 7) and the
 * three columns d2J_i/dx drho for rho_i, rho_j1, rho_j2 (eq. 8, analytic dC/drho). */
struct TermDerivatives
{
  Eigen::Matrix3d H;
  Eigen::Vector3d d_rho_i, d_rho_j1, d_rho_j2;
};
TermDerivatives termDerivatives(const CovarianceTerm& t, const Eigen::Vector3d& x);

/** The point-to-line cost J_i of one term (eq. 5), for numeric checks. */
double termCost(const CovarianceTerm& t, const Eigen::Vector3d& x);

/** d(n n')/drho_j1 and d(n n')/drho_j2 of eq. (9), analytic. */
void normalProjectorDerivatives(const CovarianceTerm& t, Eigen::Matrix2d& dC_j1,
                                Eigen::Matrix2d& dC_j2);

/** A posteriori variance factor of a match: the noise variance its residuals show,
 * sum_sq_residuals / (n - 3) (three parameters fitted to n point-to-line residuals), over
 * range_sigma^2, floored at 1 (1 when n <= 3). The covariance scales with the noise variance,
 * so multiplying it by this factor is the covariance under the larger of the datasheet's noise
 * and the residuals' (unmodelled structure, low overlap, a wrong local minimum). */
double residualVarianceFactor(double sum_sq_residuals, size_t n, double range_sigma);

/** Covariance of x (eq. 4, 10) with independent range noise of std `range_sigma`.
 * Directions of x that the terms do not constrain (a corridor's axis) get variance
 * `unobservable_variance` instead of an arbitrary number. */
Eigen::Matrix3d plicpCovariance(const std::vector<CovarianceTerm>& terms, const Eigen::Vector3d& x,
                                double range_sigma, double unobservable_variance = 1e6);

}  // namespace swslam::plicp

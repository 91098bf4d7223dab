#pragma once
// The adaptive robust kernel of Chebrolu et al. ("Adaptive Robust Kernels for Non-Linear
// Least Squares Problems", RA-L 2021): Barron's kernel read as a probability density,
//   P(x | alpha) = exp(-rho(x, alpha)) / Z(alpha),   x = r / c,
// truncated to |x| <= tau so that it can be normalized for every alpha (for alpha <= 0 the
// density has no finite integral over the whole line). The shape is the alpha of a grid that
// minimizes the residuals' negative log-likelihood sum_i rho(x_i, alpha) + N log Z(alpha): a
// near-Gaussian residual set gets alpha near 2 (least squares), heavy tails a low alpha.
// The scale is a robust statistic of the residuals. Pure functions over plain values.

#include <vector>

namespace swslam::graph
{
/** Z(alpha) = integral over [-tau, tau] of exp(-rho(x, alpha, c = 1)) dx (composite Simpson,
 * `intervals` even). */
double barronPartition(double alpha, double tau, int intervals = 4000);

struct ShapeEstimate
{
  double alpha = 2.0;  ///< the grid's highest when there is no residual
  double negative_log_likelihood = 0.0;  ///< per residual, at alpha
};

/** The alpha of the grid alpha_max, alpha_max - step, ..., down to alpha_min whose truncated
 * density fits the residuals best. Z is tabulated once per grid, so an estimate costs one pass over the
 * residuals per grid value. */
class ShapeEstimator
{
 public:
  /** Throws std::invalid_argument unless alpha_min <= alpha_max <= 2 (finite), step > 0 and
   * tau > 0. */
  ShapeEstimator(double alpha_min, double alpha_max, double step, double tau);

  /** Residuals r >= 0 (the Mahalanobis norms of edges) at scale c > 0; residuals beyond
   * tau c count as tau c. With no residual, alpha_max. */
  ShapeEstimate estimate(const std::vector<double>& residuals, double c) const;

  const std::vector<double>& alphas() const { return alphas_; }

 private:
  double tau_;
  std::vector<double> alphas_, log_partition_;
};

/** The estimator of this grid, tabulated once per thread and grid (a memo: tabulating Z over
 * the grid costs far more than one estimate, and the optimizer asks for it every window). */
const ShapeEstimator& shapeEstimatorFor(double alpha_min, double alpha_max, double step, double tau);

/** A robust scale of Mahalanobis residual norms of 3-dof edges: median(r) / the median of
 * the chi distribution with 3 degrees of freedom (1.5382), so that residuals whose information
 * matrices are right give 1, over-confident ones more. 1 with no residual; at least 1e-3. */
double robustResidualScale(std::vector<double> residuals);

}  // namespace swslam::graph

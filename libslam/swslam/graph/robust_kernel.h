#pragma once
// Barron's general robust kernel (paper eq. 14, Barron CVPR 2019) and the IRLS weight
// w = rho'(r) / r of eq. 13. Pure functions over plain values.

#include <limits>

namespace swslam::graph
{
/** Shape `alpha` in [-inf, 2] and scale `c` > 0 of Barron's kernel. Special cases:
 * alpha = 2 L2, 1 pseudo-Huber ("L1"), 0 Cauchy/Lorentzian, -2 Geman-McClure, -inf Welsch. */
struct BarronKernel
{
  double alpha = 0.0;
  double c = 1.0;
};

/** Minus infinity, the Welsch limit of alpha. */
constexpr double kAlphaWelsch = -std::numeric_limits<double>::infinity();

/** Throws std::invalid_argument unless alpha is in [-inf, 2] (not NaN) and c is finite > 0. */
void checkKernel(const BarronKernel& k);

/** rho(r, alpha, c) of eq. 14; the removable singularities alpha = 2 (0/0), alpha = 0 (0/0)
 * and alpha = -inf are evaluated by their exact limits. */
double barronRho(double r, const BarronKernel& k);

/** d rho / d r. */
double barronRhoDerivative(double r, const BarronKernel& k);

/** The IRLS weight of eq. 13, rho'(r) / r, with its limit 1/c^2 at r = 0. */
double barronWeight(double r, const BarronKernel& k);

/** c^2 * barronWeight(): the weight scaled so that a small residual weighs 1, as in plain
 * least squares. This is what the optimizer multiplies each robustified edge by, so that
 * robustified and non-robustified edges agree for inliers and c only sets where
 * down-weighting begins. */
double normalizedBarronWeight(double r, const BarronKernel& k);

/** c^2 * barronRho(): the cost whose IRLS weight is normalizedBarronWeight(); it equals
 * r^2 / 2 for alpha = 2. */
double normalizedBarronRho(double r, const BarronKernel& k);

}  // namespace swslam::graph

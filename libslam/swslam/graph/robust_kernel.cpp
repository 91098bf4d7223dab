#include <swslam/graph/robust_kernel.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace swslam::graph
{
void checkKernel(const BarronKernel& k)
{
  if (std::isnan(k.alpha) || k.alpha > 2.0)
    throw std::invalid_argument("robust kernel: alpha must be in [-inf, 2], got " +
                                std::to_string(k.alpha));
  if (!std::isfinite(k.c) || k.c <= 0.0)
    throw std::invalid_argument("robust kernel: scale c must be finite and > 0, got " +
                                std::to_string(k.c));
}

double barronRho(double r, const BarronKernel& k)
{
  const double z = (r / k.c) * (r / k.c);  // (r/c)^2
  if (k.alpha == 2.0) return 0.5 * z;                      // L2
  if (k.alpha == 0.0) return std::log1p(0.5 * z);          // Cauchy / Lorentzian
  if (std::isinf(k.alpha)) return -std::expm1(-0.5 * z);   // Welsch
  // Eq. 14 written with expm1/log1p, accurate for alpha near 0 and 2.
  const double b = std::abs(k.alpha - 2.0);
  return b / k.alpha * std::expm1(0.5 * k.alpha * std::log1p(z / b));
}

double barronWeight(double r, const BarronKernel& k)
{
  // rho'(r) = r / c^2 * ((r/c)^2 / |alpha-2| + 1)^(alpha/2 - 1), so the weight needs no
  // special case at alpha = 0, only at alpha = 2 (0/0 inside) and alpha = -inf.
  const double inv_c2 = 1.0 / (k.c * k.c);
  const double z = r * r * inv_c2;
  if (k.alpha == 2.0) return inv_c2;
  if (std::isinf(k.alpha)) return inv_c2 * std::exp(-0.5 * z);
  const double b = std::abs(k.alpha - 2.0);
  return inv_c2 * std::exp((0.5 * k.alpha - 1.0) * std::log1p(z / b));
}

double barronRhoDerivative(double r, const BarronKernel& k) { return r * barronWeight(r, k); }

double normalizedBarronWeight(double r, const BarronKernel& k)
{
  return k.c * k.c * barronWeight(r, k);
}

double normalizedBarronRho(double r, const BarronKernel& k) { return k.c * k.c * barronRho(r, k); }

}  // namespace swslam::graph

#include <swslam/geometry/se2_scaling.h>

#include <cmath>

namespace swslam::geometry
{
namespace
{
/** sin(t)/t and (1 - cos(t))/t, with their series near 0. */
void vCoefficients(double t, double& a, double& b)
{
  if (std::abs(t) < 1e-4)
  {
    a = 1 - t * t / 6;
    b = t / 2 - t * t * t / 24;
    return;
  }
  a = std::sin(t) / t;
  b = (1 - std::cos(t)) / t;
}
}  // namespace

mrpt::poses::CPose2D scaledMotion(const mrpt::poses::CPose2D& m, double s)
{
  if (s == 1) return m;  // exactly, not up to rounding
  // log: the translation is V(theta) u with V = [a -b; b a]; exp at s theta maps s u back.
  const double theta = m.phi();
  double a, b;
  vCoefficients(theta, a, b);
  const double det = a * a + b * b;  // > 0 for |theta| <= pi
  const double ux = (a * m.x() + b * m.y()) / det, uy = (-b * m.x() + a * m.y()) / det;
  vCoefficients(s * theta, a, b);
  return {s * (a * ux - b * uy), s * (b * ux + a * uy), s * theta};
}

}  // namespace swslam::geometry

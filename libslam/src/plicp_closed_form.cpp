#include "swslam/plicp/closed_form.h"

#include <Eigen/Dense>
#include <unsupported/Eigen/Polynomials>

#include <cmath>
#include <limits>

namespace swslam::plicp
{
namespace
{
Eigen::Matrix2d adjugate(const Eigen::Matrix2d& S)
{
  Eigen::Matrix2d a;
  a << S(1, 1), -S(0, 1), -S(1, 0), S(0, 0);
  return a;
}

struct Reduced
{
  Eigen::Matrix2d Ainv, B, S;
  Eigen::Vector2d h;
};

/** Eliminates the translation: min over t of the cost leaves u'Su + h'u, u = (cos, sin). */
Reduced reduce(const Eigen::Matrix4d& M, const Eigen::Vector4d& g)
{
  Reduced r;
  const Eigen::Matrix2d A = M.topLeftCorner<2, 2>();
  r.B = M.topRightCorner<2, 2>();
  const Eigen::Matrix2d D = M.bottomRightCorner<2, 2>();
  r.Ainv = A.inverse();
  r.S = D - r.B.transpose() * r.Ainv * r.B;
  r.h = g.tail<2>() - r.B.transpose() * r.Ainv * g.head<2>();
  return r;
}

/** Translation that minimizes the cost for a given unit vector u. */
Eigen::Vector2d bestTranslation(const Reduced& r, const Eigen::Vector4d& g, const Eigen::Vector2d& u)
{
  return -r.Ainv * (r.B * u + 0.5 * g.head<2>());
}

double reducedCost(const Reduced& r, const Eigen::Vector2d& u)
{
  return u.dot(r.S * u) + r.h.dot(u);
}

/** Dense search over the angle, then Newton on f(th) = u'Su + h'u. */
double minimizeAngleBySearch(const Reduced& r)
{
  constexpr int kSamples = 720;
  double best_th = 0, best_f = std::numeric_limits<double>::infinity();
  for (int k = 0; k < kSamples; k++)
  {
    const double th = -M_PI + 2 * M_PI * k / kSamples;
    const double f = reducedCost(r, {std::cos(th), std::sin(th)});
    if (f < best_f)
    {
      best_f = f;
      best_th = th;
    }
  }
  for (int it = 0; it < 20; it++)
  {
    const Eigen::Vector2d u(std::cos(best_th), std::sin(best_th)), du(-u.y(), u.x());
    const double f1 = 2 * du.dot(r.S * u) + r.h.dot(du);
    const double f2 = 2 * du.dot(r.S * du) - 2 * u.dot(r.S * u) - r.h.dot(u);
    if (!(f2 > 0)) break;
    const double step = f1 / f2;
    best_th -= step;
    if (std::abs(step) < 1e-15) break;
  }
  return best_th;
}
}  // namespace

void buildCost(const std::vector<PointToLine>& terms, Eigen::Matrix4d& M, Eigen::Vector4d& g)
{
  M.setZero();
  g.setZero();
  for (const auto& t : terms)
  {
    // Residual n'(R p + t - q) = J x - n'q with J = n' [1 0 px -py; 0 1 py px]:
    // the cost adds J'J to M and -2 (n'q) J' to g (a rank-one update).
    const Eigen::Vector4d J(t.n.x(), t.n.y(), t.n.x() * t.p.x() + t.n.y() * t.p.y(),
                            t.n.y() * t.p.x() - t.n.x() * t.p.y());
    for (int r = 0; r < 4; r++)
      for (int c = r; c < 4; c++) M(r, c) += J(r) * J(c);
    g -= 2 * t.n.dot(t.q) * J;
  }
  M.triangularView<Eigen::StrictlyLower>() = M.transpose();
}

std::array<double, 5> quarticCoefficients(const Eigen::Matrix4d& M, const Eigen::Vector4d& g)
{
  const Reduced r = reduce(M, g);
  const double tr = r.S.trace(), det = r.S.determinant();
  const Eigen::Matrix2d SA = adjugate(r.S);
  const double hh = r.h.dot(r.h), hSh = r.h.dot(SA * r.h), hSSh = (SA * r.h).squaredNorm();
  return {16, 32 * tr, 16 * tr * tr + 32 * det - 4 * hh, 32 * tr * det - 8 * hSh,
          16 * det * det - 4 * hSSh};
}

std::array<double, 5> quarticCoefficientsAsPrinted(const Eigen::Matrix4d& M,
                                                   const Eigen::Vector4d& g)
{
  const Reduced r = reduce(M, g);
  const double tr = r.S.trace(), det = r.S.determinant();
  const Eigen::Matrix2d SA = adjugate(r.S);
  const double hh = r.h.dot(r.h), hSh = r.h.dot(SA * r.h), hSSh = (SA * r.h).squaredNorm();
  return {16, 16 * tr, 8 * det + 4 * tr * tr - 4 * hh, 4 * det * tr - 4 * hSh,
          det * det - hSSh};
}

double lagrangeConstraintResidual(const Eigen::Matrix4d& M, const Eigen::Vector4d& g,
                                  double lambda)
{
  Eigen::Matrix4d W = Eigen::Matrix4d::Zero();
  W(2, 2) = W(3, 3) = 1;
  const Eigen::Matrix4d K = 2 * M + 2 * lambda * W;
  const Eigen::Vector4d v = K.transpose().fullPivLu().solve(g);  // K^-T g
  return v.dot(W * v) - 1;
}

std::vector<double> quarticRealRoots(const std::array<double, 5>& c)
{
  // Normalize to a monic polynomial, coefficients in increasing degree for Eigen.
  Eigen::Matrix<double, 5, 1> poly;
  poly << c[4] / c[0], c[3] / c[0], c[2] / c[0], c[1] / c[0], 1.0;
  Eigen::PolynomialSolver<double, 4> solver(poly);
  std::vector<double> roots;
  const double scale = 1 + poly.head<4>().cwiseAbs().maxCoeff();
  for (const auto& z : solver.roots())
  {
    if (std::abs(z.imag()) > 1e-6 * (1 + std::abs(z.real())) * std::sqrt(scale)) continue;
    double x = z.real();
    for (int it = 0; it < 8; it++)  // Newton polish
    {
      const double p = Eigen::poly_eval(poly, x);
      const double dp = ((4 * x + 3 * poly(3)) * x + 2 * poly(2)) * x + poly(1);
      if (dp == 0) break;
      const double nx = x - p / dp;
      if (!std::isfinite(nx)) break;
      if (std::abs(nx - x) < 1e-15 * (1 + std::abs(x))) break;
      x = nx;
    }
    roots.push_back(x);
  }
  return roots;
}

std::optional<Eigen::Vector3d> minimizeOnCircle(const Eigen::Matrix4d& M, const Eigen::Vector4d& g)
{
  if (!M.allFinite() || !g.allFinite()) return std::nullopt;
  const Reduced r = reduce(M, g);
  if (!r.Ainv.allFinite()) return std::nullopt;

  // Each real root lambda gives u = -(S + lambda I)^-1 h / 2 (stationary points on the circle).
  double best_f = std::numeric_limits<double>::infinity();
  Eigen::Vector2d best_u(1, 0);
  bool found = false;
  for (double lambda : quarticRealRoots(quarticCoefficients(M, g)))
  {
    const Eigen::Matrix2d Q = r.S + lambda * Eigen::Matrix2d::Identity();
    if (std::abs(Q.determinant()) < 1e-12 * (1 + Q.squaredNorm())) continue;
    Eigen::Vector2d u = -0.5 * Q.inverse() * r.h;
    if (!u.allFinite() || std::abs(u.norm() - 1) > 1e-3) continue;
    u.normalize();
    const double f = reducedCost(r, u);
    if (f < best_f)
    {
      best_f = f;
      best_u = u;
      found = true;
    }
  }
  // Degenerate cost (h ~ 0, double roots, no usable root): search the angle directly.
  if (!found)
  {
    const double th = minimizeAngleBySearch(r);
    best_u = Eigen::Vector2d(std::cos(th), std::sin(th));
  }

  const Eigen::Vector2d t = bestTranslation(r, g, best_u);
  return Eigen::Vector3d(t.x(), t.y(), std::atan2(best_u.y(), best_u.x()));
}

std::optional<Eigen::Vector3d> solvePointToLine(const std::vector<PointToLine>& terms,
                                                const Eigen::Vector3d& anchor)
{
  Eigen::Matrix4d M;
  Eigen::Vector4d g;
  buildCost(terms, M, g);
  // eps * |x - x_anchor|^2: negligible against any constrained direction.
  const double eps = 1e-9 * std::max(1.0, M.trace());
  const Eigen::Vector4d xa(anchor.x(), anchor.y(), std::cos(anchor.z()), std::sin(anchor.z()));
  M += eps * Eigen::Matrix4d::Identity();
  g -= 2 * eps * xa;
  return minimizeOnCircle(M, g);
}

}  // namespace swslam::plicp

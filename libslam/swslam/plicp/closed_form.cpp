#include <swslam/plicp/closed_form.h>

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

namespace
{
/** The unit vector of least u'Su + h'u from the Lagrange condition 2(S + lambda I)u = -h
 * with S + lambda I positive semi-definite, which singles out the global minimum (the
 * trust-region argument): in S's eigenbasis (l1 <= l2, h -> a), with mu = lambda + l1 > 0
 * and d = l2 - l1, |u|^2 = a1^2/(4 mu^2) + a2^2/(4 (mu + d)^2) decreases from its value at
 * 0+ to 0, so |u| = 1 has one root, found by safeguarded Newton on 1/|u| - 1 (concave).
 * When a1 = 0 and |u(0+)| <= 1 (the "hard case"), mu = 0 and u gets the missing length
 * along the first eigenvector. Nothing if no finite solution comes out. */
std::optional<Eigen::Vector2d> unitMinimizerBySecularEquation(const Reduced& r)
{
  const double p = r.S(0, 0), q = 0.5 * (r.S(0, 1) + r.S(1, 0)), s = r.S(1, 1);
  const double half_diff = 0.5 * (p - s), rad = std::hypot(half_diff, q);
  const double d = 2 * rad;  // l2 - l1
  const double phi = 0.5 * std::atan2(q, half_diff);
  const Eigen::Vector2d v2(std::cos(phi), std::sin(phi)), v1(-v2.y(), v2.x());
  const double a1 = v1.dot(r.h), a2 = v2.dot(r.h);
  const double norm_a = std::hypot(a1, a2);
  Eigen::Vector2d w;  // u in the eigenbasis
  const bool hard = a1 == 0 && (d > 0 ? a2 * a2 <= 4 * d * d : a2 == 0);
  if (hard)
  {
    const double w2 = d > 0 ? -a2 / (2 * d) : 0.0;
    w = {std::sqrt(std::max(0.0, 1 - w2 * w2)), w2};
  }
  else
  {
    auto norm2 = [&](double mu) {
      return a1 * a1 / (4 * mu * mu) + a2 * a2 / (4 * (mu + d) * (mu + d));
    };
    double lo = 0, hi = 0.5 * norm_a;  // |u(hi)| <= 1 < |u(0+)|
    double mu = std::max(0.5 * std::abs(a1), 0.5 * std::abs(a2) - d);  // |u(mu)| >= 1
    if (!(mu > 0)) mu = 0.5 * hi;
    for (int it = 0; it < 100; it++)
    {
      const double n2 = norm2(mu);
      const double psi = 1 / std::sqrt(n2) - 1;
      if (psi < 0) lo = mu;
      else hi = mu;
      const double dn2 = -a1 * a1 / (2 * mu * mu * mu) -
                         a2 * a2 / (2 * (mu + d) * (mu + d) * (mu + d));
      const double dpsi = -0.5 * dn2 / (n2 * std::sqrt(n2));
      double next = mu - psi / dpsi;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - mu) <= 1e-15 * mu || hi - lo <= 1e-15 * hi)
      {
        mu = next;
        break;
      }
      mu = next;
    }
    w = {-a1 / (2 * mu), -a2 / (2 * (mu + d))};
  }
  const Eigen::Vector2d u = w.x() * v1 + w.y() * v2;
  if (!u.allFinite() || std::abs(u.norm() - 1) > 1e-3) return std::nullopt;
  return u.normalized();
}

/** The minimizer over the roots of the quartic of eq. (3) (slower: a 4x4 eigenvalue
 * problem), used when the secular equation gives no usable answer. */
std::optional<Eigen::Vector2d> unitMinimizerByQuartic(const Eigen::Matrix4d& M,
                                                      const Eigen::Vector4d& g, const Reduced& r)
{
  // Each real root lambda gives u = -(S + lambda I)^-1 h / 2 (stationary points on the circle).
  double best_f = std::numeric_limits<double>::infinity();
  std::optional<Eigen::Vector2d> best;
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
      best = u;
    }
  }
  return best;
}

std::optional<Eigen::Vector3d> minimize(const Eigen::Matrix4d& M, const Eigen::Vector4d& g,
                                        bool by_quartic)
{
  if (!M.allFinite() || !g.allFinite()) return std::nullopt;
  const Reduced r = reduce(M, g);
  if (!r.Ainv.allFinite()) return std::nullopt;
  auto u = by_quartic ? unitMinimizerByQuartic(M, g, r) : unitMinimizerBySecularEquation(r);
  if (!u && !by_quartic) u = unitMinimizerByQuartic(M, g, r);
  // Degenerate cost (double roots, no usable root): search the angle directly.
  if (!u)
  {
    const double th = minimizeAngleBySearch(r);
    u = Eigen::Vector2d(std::cos(th), std::sin(th));
  }
  const Eigen::Vector2d t = bestTranslation(r, g, *u);
  return Eigen::Vector3d(t.x(), t.y(), std::atan2(u->y(), u->x()));
}
}  // namespace

std::optional<Eigen::Vector3d> minimizeOnCircle(const Eigen::Matrix4d& M, const Eigen::Vector4d& g)
{
  return minimize(M, g, false);
}

std::optional<Eigen::Vector3d> minimizeOnCircleByQuartic(const Eigen::Matrix4d& M,
                                                         const Eigen::Vector4d& g)
{
  return minimize(M, g, true);
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

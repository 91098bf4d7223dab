#include <swslam/plicp/covariance.h>

#include <Eigen/Dense>

#include <cmath>
#include <algorithm>
#include <vector>

namespace swslam::plicp
{
namespace
{
Eigen::Matrix2d rot(double a)
{
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix2d R;
  R << c, -s, s, c;
  return R;
}

/** Unit normal of the reference segment p_j1 - p_j2 (rotated by +90 deg). */
Eigen::Vector2d normalOf(const Eigen::Vector2d& q1, const Eigen::Vector2d& q2)
{
  const Eigen::Vector2d e = (q1 - q2).normalized();
  return {-e.y(), e.x()};
}
}  // namespace

double termCost(const CovarianceTerm& t, const Eigen::Vector3d& x)
{
  const Eigen::Vector2d q1 = t.rho_j1 * t.dir_j1, q2 = t.rho_j2 * t.dir_j2;
  const Eigen::Vector2d n = normalOf(q1, q2);
  const double r = n.dot(rot(x.z()) * (t.rho_i * t.dir_i) + x.head<2>() - q1);
  return r * r;
}

void normalProjectorDerivatives(const CovarianceTerm& t, Eigen::Matrix2d& dC_j1,
                                Eigen::Matrix2d& dC_j2)
{
  const Eigen::Vector2d d = t.rho_j1 * t.dir_j1 - t.rho_j2 * t.dir_j2;
  const double L = d.norm();
  const Eigen::Vector2d e = d / L;
  const Eigen::Vector2d n(-e.y(), e.x());
  Eigen::Matrix2d R90;
  R90 << 0, -1, 1, 0;
  const Eigen::Matrix2d dn_dd = R90 * (Eigen::Matrix2d::Identity() - e * e.transpose()) / L;
  const Eigen::Vector2d dn1 = dn_dd * t.dir_j1, dn2 = -dn_dd * t.dir_j2;
  dC_j1 = dn1 * n.transpose() + n * dn1.transpose();
  dC_j2 = dn2 * n.transpose() + n * dn2.transpose();
}

namespace
{
/** termDerivatives() with R = rot(x.z()) given (computed once for all terms). */
TermDerivatives derivativesWith(const CovarianceTerm& t, const Eigen::Vector3d& x,
                                const Eigen::Matrix2d& R)
{
  Eigen::Matrix2d R90;  // R(th + pi/2) = R90 R(th), R(th + pi) = -R(th)
  R90 << 0, -1, 1, 0;
  const Eigen::Vector2d p = t.rho_i * t.dir_i;
  const Eigen::Vector2d q1 = t.rho_j1 * t.dir_j1, q2 = t.rho_j2 * t.dir_j2;
  const Eigen::Vector2d n = normalOf(q1, q2);
  const Eigen::Matrix2d C = n * n.transpose();
  // The vectors of the paper's eq. (7)-(8).
  const Eigen::Vector2d Rp = R * p;
  const Eigen::Vector2d v1 = R90 * Rp;
  const Eigen::Vector2d v2 = Rp + x.head<2>() - q1;
  const Eigen::Vector2d v3 = R * t.dir_i;
  const Eigen::Vector2d v4 = R90 * v3;
  const Eigen::Vector2d v5 = -Rp;
  Eigen::Matrix2d dC1, dC2;
  normalProjectorDerivatives(t, dC1, dC2);

  TermDerivatives out;
  out.H.topLeftCorner<2, 2>() = 2 * C;
  out.H.topRightCorner<2, 1>() = 2 * C * v1;
  out.H.bottomLeftCorner<1, 2>() = 2 * v1.transpose() * C;
  out.H(2, 2) = 2 * v2.dot(C * v5) + 2 * v1.dot(C * v1);

  out.d_rho_i << 2 * C * v3, 2 * v2.dot(C * v4) + 2 * v3.dot(C * v1);
  out.d_rho_j1 << -2 * C * t.dir_j1 + 2 * dC1 * v2, 2 * v2.dot(dC1 * v1) - 2 * v1.dot(C * t.dir_j1);
  out.d_rho_j2 << 2 * dC2 * v2, 2 * v2.dot(dC2 * v1);
  return out;
}
}  // namespace

TermDerivatives termDerivatives(const CovarianceTerm& t, const Eigen::Vector3d& x)
{
  return derivativesWith(t, x, rot(x.z()));
}

double residualVarianceFactor(double sum_sq_residuals, size_t n, double range_sigma)
{
  if (n <= 3) return 1.0;
  return std::max(1.0, sum_sq_residuals / (static_cast<double>(n - 3) * range_sigma * range_sigma));
}

Eigen::Matrix3d plicpCovariance(const std::vector<CovarianceTerm>& terms, const Eigen::Vector3d& x,
                                double range_sigma, double unobservable_variance)
{
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  // One column of d2J/dxdz per measured range (eq. 6), summed over the terms using it.
  int max_cur = -1, max_ref = -1;
  for (const auto& t : terms)
  {
    max_cur = std::max(max_cur, t.ray_i);
    max_ref = std::max({max_ref, t.ray_j1, t.ray_j2});
  }
  std::vector<Eigen::Vector3d> cur_cols(max_cur + 1, Eigen::Vector3d::Zero()),
      ref_cols(max_ref + 1, Eigen::Vector3d::Zero());
  const Eigen::Matrix2d R = rot(x.z());
  for (const auto& t : terms)
  {
    const TermDerivatives d = derivativesWith(t, x, R);
    H += d.H;
    cur_cols[t.ray_i] += d.d_rho_i;
    ref_cols[t.ray_j1] += d.d_rho_j1;
    ref_cols[t.ray_j2] += d.d_rho_j2;
  }
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  for (const auto* cols : {&cur_cols, &ref_cols})
    for (const auto& c : *cols) N += c * c.transpose();
  N *= range_sigma * range_sigma;

  // H^-1 restricted to the observable directions; unobservable ones get a large variance.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(0.5 * (H + H.transpose()));
  const double tol = 1e-9 * std::max(1e-300, es.eigenvalues().cwiseAbs().maxCoeff());
  Eigen::Matrix3d Hinv = Eigen::Matrix3d::Zero(), unobservable = Eigen::Matrix3d::Zero();
  for (int k = 0; k < 3; k++)
  {
    const Eigen::Vector3d v = es.eigenvectors().col(k);
    if (es.eigenvalues()(k) > tol) Hinv += v * v.transpose() / es.eigenvalues()(k);
    else unobservable += unobservable_variance * v * v.transpose();
  }
  return Hinv * N * Hinv + unobservable;
}

}  // namespace swslam::plicp

#include <swslam/graph/node_merge.h>

#include <swslam/geometry/se2_error.h>

#include <Eigen/Dense>

#include <cmath>

namespace swslam::graph
{
namespace
{
using mrpt::poses::CPosePDFGaussian;
using mrpt::poses::CPosePDFGaussianInf;

/** R(theta) on the translation, 1 on the angle: the measurement frame to its parent's. */
Eigen::Matrix3d turn(double theta)
{
  Eigen::Matrix3d G = Eigen::Matrix3d::Identity();
  const double c = std::cos(theta), s = std::sin(theta);
  G.topLeftCorner<2, 2>() << c, -s, s, c;
  return G;
}

CPosePDFGaussian asGaussian(const CPosePDFGaussianInf& z) { return measurementGaussian(z.mean, z.cov_inv.asEigen()); }

/** The inverse of measurementGaussian. */
CPosePDFGaussianInf asMeasurement(const CPosePDFGaussian& p)
{
  const Eigen::Matrix3d G = turn(p.mean.phi());
  Eigen::Matrix3d info = (G.transpose() * p.cov.asEigen() * G).inverse();
  info = 0.5 * (info + info.transpose());
  return CPosePDFGaussianInf(p.mean, mrpt::math::CMatrixDouble33(info));
}
}  // namespace

CPosePDFGaussian measurementGaussian(const mrpt::poses::CPose2D& mean, const Eigen::Matrix3d& information)
{
  const Eigen::Matrix3d G = turn(mean.phi());
  return CPosePDFGaussian(mean, mrpt::math::CMatrixDouble33(G * information.inverse() * G.transpose()));
}

CPosePDFGaussianInf carryEdge(const CPosePDFGaussianInf* from_attachment, const CPosePDFGaussianInf& z,
                              const CPosePDFGaussianInf* to_attachment)
{
  CPosePDFGaussian out;  // identity, no uncertainty
  if (from_attachment) out += asGaussian(*from_attachment);
  out += asGaussian(z);
  if (to_attachment)
  {
    CPosePDFGaussian back;
    asGaussian(*to_attachment).inverse(back);
    out += back;
  }
  return asMeasurement(out);
}

std::optional<CPosePDFGaussianInf> fuseAgreeing(const CPosePDFGaussianInf& a, const CPosePDFGaussianInf& b,
                                                double gate)
{
  // b's error seen in a's frame: delta = t2v(a^-1 (+) b); b's information turned into that
  // frame by the small rotation between the two.
  const mrpt::poses::CPose2D d = b.mean - a.mean;
  const Eigen::Vector3d delta(d.x(), d.y(), d.phi());
  const Eigen::Matrix3d J = turn(d.phi());
  const Eigen::Matrix3d Ia = a.cov_inv.asEigen(), Ib = J * b.cov_inv.asEigen() * J.transpose();
  const Eigen::Matrix3d S = Ia.inverse() + Ib.inverse();
  if (!(delta.dot(S.ldlt().solve(delta)) <= gate)) return std::nullopt;
  // w on a grid from 0.5 outwards: the first of the largest determinant wins a tie.
  double best_w = 0.5, best_det = -1;
  for (int k = 0; k <= 20; ++k)
  {
    const double w = 0.5 + (k % 2 ? 1 : -1) * 0.05 * ((k + 1) / 2);
    const double det = (w * Ia + (1 - w) * Ib).determinant();
    if (det > best_det * (1 + 1e-12)) best_det = det, best_w = w;
  }
  Eigen::Matrix3d I = best_w * Ia + (1 - best_w) * Ib;
  I = 0.5 * (I + I.transpose());
  const Eigen::Vector3d mu = I.ldlt().solve((1 - best_w) * Ib * delta);
  return CPosePDFGaussianInf(a.mean + mrpt::poses::CPose2D(mu.x(), mu.y(), mu.z()), mrpt::math::CMatrixDouble33(I));
}

}  // namespace swslam::graph

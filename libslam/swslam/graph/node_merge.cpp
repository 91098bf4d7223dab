#include <swslam/graph/node_merge.h>

#include <mrpt/poses/CPosePDFGaussian.h>

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

/** The measurement as MRPT's Gaussian: covariance in the frame of the edge's first pose. */
CPosePDFGaussian asGaussian(const CPosePDFGaussianInf& z)
{
  const Eigen::Matrix3d G = turn(z.mean.phi());
  return CPosePDFGaussian(z.mean, mrpt::math::CMatrixDouble33(G * z.cov_inv.asEigen().inverse() * G.transpose()));
}

CPosePDFGaussianInf asMeasurement(const CPosePDFGaussian& p)
{
  const Eigen::Matrix3d G = turn(p.mean.phi());
  Eigen::Matrix3d info = (G.transpose() * p.cov.asEigen() * G).inverse();
  info = 0.5 * (info + info.transpose());
  return CPosePDFGaussianInf(p.mean, mrpt::math::CMatrixDouble33(info));
}
}  // namespace

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

}  // namespace swslam::graph

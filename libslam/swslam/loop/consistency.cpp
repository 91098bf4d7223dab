#include <swslam/loop/consistency.h>

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Eigenvalues>

#include <limits>

namespace swslam::loop
{
using mrpt::poses::CPose2D;

Eigen::Vector3d loopPairError(const CPose2D& z1, const CPose2D& z2, const CPose2D& rel_ab,
                              const CPose2D& rel_nm)
{
  const CPose2D via_n = z1 + rel_nm;  // a -> n -> m
  const CPose2D via_b = rel_ab + z2;  // a -> b -> m
  const CPose2D e = via_b - via_n;    // via_n^-1 (+) via_b
  return {e.x(), e.y(), mrpt::math::wrapToPi(e.phi())};
}

double loopPairChi2(const LoopEdgeMeasure& l1, const LoopEdgeMeasure& l2, const CPose2D& rel_ab,
                    const CPose2D& rel_nm, double local_sigma_xy, double local_sigma_theta)
{
  const Eigen::Vector3d e = loopPairError(l1.z, l2.z, rel_ab, rel_nm);
  auto largestXy = [](const Eigen::Matrix3d& c) {
    const Eigen::Matrix2d xy = 0.5 * (c.topLeftCorner<2, 2>() + c.topLeftCorner<2, 2>().transpose());
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(xy, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
  };
  const double v_xy = largestXy(l1.covariance) + largestXy(l2.covariance) + local_sigma_xy * local_sigma_xy;
  const double v_th = l1.covariance(2, 2) + l2.covariance(2, 2) + local_sigma_theta * local_sigma_theta;
  if (!e.allFinite() || !(v_xy > 0) || !(v_th > 0)) return std::numeric_limits<double>::infinity();
  return (e.x() * e.x() + e.y() * e.y()) / v_xy + e.z() * e.z() / v_th;
}

}  // namespace swslam::loop

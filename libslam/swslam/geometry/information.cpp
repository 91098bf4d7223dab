#include <swslam/geometry/information.h>

#include <Eigen/Eigenvalues>

namespace swslam::geometry
{
Eigen::Matrix3d informationFromCovariance(const Eigen::Matrix3d& cov, double min_variance)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(0.5 * (cov + cov.transpose()));
  const Eigen::Vector3d inv = es.eigenvalues().cwiseMax(min_variance).cwiseInverse();
  return es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose();
}

}  // namespace swslam::geometry

#include "swslam/se2_error.h"

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace swslam
{
double wrapAngle(double a) { return mrpt::math::wrapToPi(a); }

Eigen::Vector3d se2Error(const Pose2& xi, const Pose2& xj, const Pose2& z)
{
  Eigen::Matrix3d Ji, Jj;
  return se2ErrorWithJacobians(xi, xj, z, Ji, Jj);
}

Eigen::Vector3d se2ErrorWithJacobians(const Pose2& xi, const Pose2& xj, const Pose2& z,
                                      Eigen::Matrix3d& Ji, Eigen::Matrix3d& Jj)
{
  const double ci = std::cos(xi.z()), si = std::sin(xi.z());
  const double cz = std::cos(z.z()), sz = std::sin(z.z());
  const double dx = xj.x() - xi.x(), dy = xj.y() - xi.y();
  // d = R_i^T (t_j - t_i): node j in the frame of node i.
  const double d0 = ci * dx + si * dy;
  const double d1 = -si * dx + ci * dy;
  const double u0 = d0 - z.x(), u1 = d1 - z.y();
  Eigen::Vector3d e(cz * u0 + sz * u1, -sz * u0 + cz * u1, wrapAngle(xj.z() - xi.z() - z.z()));

  // A = R_z^T R_i^T = R(theta_i + theta_z)^T.
  const double ca = std::cos(xi.z() + z.z()), sa = std::sin(xi.z() + z.z());
  // d d / d theta_i = (d1, -d0); rotated by R_z^T.
  const double g0 = cz * d1 - sz * d0;
  const double g1 = -sz * d1 - cz * d0;
  Ji << -ca, -sa, g0,  //
      sa, -ca, g1,     //
      0, 0, -1;
  Jj << ca, sa, 0,  //
      -sa, ca, 0,   //
      0, 0, 1;
  return e;
}

Pose2 composePose(const Pose2& a, const Pose2& b)
{
  const double c = std::cos(a.z()), s = std::sin(a.z());
  return Pose2(a.x() + c * b.x() - s * b.y(), a.y() + s * b.x() + c * b.y(),
               wrapAngle(a.z() + b.z()));
}

Pose2 relativePose(const Pose2& a, const Pose2& b)
{
  const double c = std::cos(a.z()), s = std::sin(a.z());
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  return Pose2(c * dx + s * dy, -s * dx + c * dy, wrapAngle(b.z() - a.z()));
}

}  // namespace swslam

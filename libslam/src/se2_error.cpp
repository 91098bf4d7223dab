#include "swslam/se2_error.h"

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace swslam
{
double wrapAngle(double a) { return mrpt::math::wrapToPi(a); }

namespace
{
/** The parts of e_ij that its Jacobians share: R_i^T (t_j - t_i) and the rotations. */
struct Se2Terms
{
  double ci, si, cz, sz;  ///< cos/sin of theta_i and theta_z
  double d0, d1;          ///< d = R_i^T (t_j - t_i): node j in the frame of node i
  Eigen::Vector3d e;
};

Se2Terms se2Terms(const Pose2& xi, const Pose2& xj, const Pose2& z)
{
  Se2Terms t;
  t.ci = std::cos(xi.z()), t.si = std::sin(xi.z());
  t.cz = std::cos(z.z()), t.sz = std::sin(z.z());
  const double dx = xj.x() - xi.x(), dy = xj.y() - xi.y();
  t.d0 = t.ci * dx + t.si * dy;
  t.d1 = -t.si * dx + t.ci * dy;
  const double u0 = t.d0 - z.x(), u1 = t.d1 - z.y();
  t.e = Eigen::Vector3d(t.cz * u0 + t.sz * u1, -t.sz * u0 + t.cz * u1,
                        wrapAngle(xj.z() - xi.z() - z.z()));
  return t;
}
}  // namespace

Eigen::Vector3d se2Error(const Pose2& xi, const Pose2& xj, const Pose2& z)
{
  return se2Terms(xi, xj, z).e;
}

Eigen::Vector3d se2ErrorWithJacobians(const Pose2& xi, const Pose2& xj, const Pose2& z,
                                      Eigen::Matrix3d& Ji, Eigen::Matrix3d& Jj)
{
  const Se2Terms t = se2Terms(xi, xj, z);
  // A = R_z^T R_i^T = R(theta_i + theta_z)^T, by the angle-sum identities.
  const double ca = t.ci * t.cz - t.si * t.sz, sa = t.si * t.cz + t.ci * t.sz;
  // d d / d theta_i = (d1, -d0); rotated by R_z^T.
  const double g0 = t.cz * t.d1 - t.sz * t.d0;
  const double g1 = -t.sz * t.d1 - t.cz * t.d0;
  Ji << -ca, -sa, g0,  //
      sa, -ca, g1,     //
      0, 0, -1;
  Jj << ca, sa, 0,  //
      -sa, ca, 0,   //
      0, 0, 1;
  return t.e;
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

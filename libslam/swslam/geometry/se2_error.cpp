#include <swslam/geometry/se2_error.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace swslam::geometry
{
double wrapAngle(double a) { return mrpt::math::wrapToPi(a); }

SinCos sinCos(double angle) { return {std::cos(angle), std::sin(angle)}; }

namespace
{
/** The parts of e_ij that its Jacobians share: d = R_i^T (t_j - t_i), node j in the frame
 * of node i, and e itself. */
struct Se2Terms
{
  double d0, d1;
  Eigen::Vector3d e;
};

Se2Terms se2Terms(const Pose2& xi, const Pose2& xj, const Pose2& z, SinCos ri, SinCos rz)
{
  Se2Terms t;
  const double dx = xj.x() - xi.x(), dy = xj.y() - xi.y();
  t.d0 = ri.c * dx + ri.s * dy;
  t.d1 = -ri.s * dx + ri.c * dy;
  const double u0 = t.d0 - z.x(), u1 = t.d1 - z.y();
  t.e = Eigen::Vector3d(rz.c * u0 + rz.s * u1, -rz.s * u0 + rz.c * u1,
                        wrapAngle(xj.z() - xi.z() - z.z()));
  return t;
}
}  // namespace

Eigen::Vector3d se2Error(const Pose2& xi, const Pose2& xj, const Pose2& z)
{
  return se2Error(xi, xj, z, sinCos(xi.z()), sinCos(z.z()));
}

Eigen::Vector3d se2Error(const Pose2& xi, const Pose2& xj, const Pose2& z, SinCos ri, SinCos rz)
{
  return se2Terms(xi, xj, z, ri, rz).e;
}

Eigen::Vector3d se2ErrorWithJacobians(const Pose2& xi, const Pose2& xj, const Pose2& z,
                                      Eigen::Matrix3d& Ji, Eigen::Matrix3d& Jj)
{
  return se2ErrorWithJacobians(xi, xj, z, sinCos(xi.z()), sinCos(z.z()), Ji, Jj);
}

Eigen::Vector3d se2ErrorWithJacobians(const Pose2& xi, const Pose2& xj, const Pose2& z,
                                      SinCos ri, SinCos rz, Eigen::Matrix3d& Ji,
                                      Eigen::Matrix3d& Jj)
{
  const Se2Terms t = se2Terms(xi, xj, z, ri, rz);
  // A = R_z^T R_i^T = R(theta_i + theta_z)^T, by the angle-sum identities.
  const double ca = ri.c * rz.c - ri.s * rz.s, sa = ri.s * rz.c + ri.c * rz.s;
  // d d / d theta_i = (d1, -d0); rotated by R_z^T.
  const double g0 = rz.c * t.d1 - rz.s * t.d0;
  const double g1 = -rz.s * t.d1 - rz.c * t.d0;
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

}  // namespace swslam::geometry

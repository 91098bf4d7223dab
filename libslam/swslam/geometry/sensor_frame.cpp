#include <swslam/geometry/sensor_frame.h>

#include <cmath>

namespace swslam::geometry
{
using mrpt::poses::CPose2D;

// MRPT: a + b is a (+) b, -a the inverse; a - b would be b^-1 (+) a.
CPose2D vehicleMotion(const CPose2D& s, const CPose2D& q) { return s + q + (-s); }

CPose2D sensorMotion(const CPose2D& s, const CPose2D& m) { return (-s) + m + s; }

Eigen::Matrix3d vehicleMotionCovariance(const CPose2D& s, const CPose2D& q,
                                        const Eigen::Matrix3d& cov)
{
  // m = s (+) q (+) s^-1. Its translation is t_s + R_s (t_q + R_q (-R_s' t_s)), its angle
  // phi_q (the mounting angles cancel). Derivatives w.r.t. (x_q, y_q, phi_q):
  const double cs = std::cos(s.phi()), ss = std::sin(s.phi());
  Eigen::Matrix2d Rs;
  Rs << cs, -ss, ss, cs;
  const Eigen::Vector2d ts(s.x(), s.y());
  const Eigen::Vector2d b = -Rs.transpose() * ts;  // s^-1's translation
  const double cq = std::cos(q.phi()), sq = std::sin(q.phi());
  const Eigen::Vector2d dRq_b(-sq * b.x() - cq * b.y(), cq * b.x() - sq * b.y());
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  J.topLeftCorner<2, 2>() = Rs;
  J.topRightCorner<2, 1>() = Rs * dRq_b;
  J(2, 2) = 1;
  return J * cov * J.transpose();
}

}  // namespace swslam::geometry

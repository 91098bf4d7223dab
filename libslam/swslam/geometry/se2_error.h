#pragma once
// The residual of one relative-pose constraint on SE(2) and its analytic Jacobians.
// A pose is (x, y, theta) in the world frame; poses are updated additively in these
// coordinates (x <- x + dx, theta <- wrap(theta + dtheta)).
//
//   e_ij = t2v( Z_ij^-1 * (X_i^-1 * X_j) )                                 (paper eq. 12)
//        = [ R(theta_z)^T ( R(theta_i)^T (t_j - t_i) - t_z ) ;
//            wrap(theta_j - theta_i - theta_z) ]
//
// where Z_ij is the measured pose of node j in the frame of node i. This is the residual
// of g2o's EdgeSE2 (the paper writes it as x_i - x_j with the pose-difference operator).

#include <Eigen/Core>

namespace swslam::geometry
{
using Pose2 = Eigen::Vector3d;  ///< (x, y, theta)

/** Angle wrapped to (-pi, pi]. */
double wrapAngle(double a);

/** cos and sin of an angle: a pose's, shared by all its edges, or a measurement's. */
struct SinCos
{
  double c = 1, s = 0;
};
SinCos sinCos(double angle);

/** e_ij for poses xi, xj and measurement z (pose of j seen from i). */
Eigen::Vector3d se2Error(const Pose2& xi, const Pose2& xj, const Pose2& z);

/** The same, given ri = sinCos(xi.z()) and rz = sinCos(z.z()) (an optimizer computes them
 * once per pose and per edge instead of once per edge and evaluation). */
Eigen::Vector3d se2Error(const Pose2& xi, const Pose2& xj, const Pose2& z, SinCos ri, SinCos rz);

/** e_ij and its Jacobians d e / d xi (Ji) and d e / d xj (Jj). */
Eigen::Vector3d se2ErrorWithJacobians(const Pose2& xi, const Pose2& xj, const Pose2& z,
                                      Eigen::Matrix3d& Ji, Eigen::Matrix3d& Jj);

/** The same, given ri = sinCos(xi.z()) and rz = sinCos(z.z()). */
Eigen::Vector3d se2ErrorWithJacobians(const Pose2& xi, const Pose2& xj, const Pose2& z,
                                      SinCos ri, SinCos rz, Eigen::Matrix3d& Ji,
                                      Eigen::Matrix3d& Jj);

/** Composition a (+) b: pose b given in the frame of a, expressed in the world frame. */
Pose2 composePose(const Pose2& a, const Pose2& b);

/** Pose of b in the frame of a: a^-1 (+) b. */
Pose2 relativePose(const Pose2& a, const Pose2& b);

}  // namespace swslam::geometry

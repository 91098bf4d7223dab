#include <swslam/geometry/sensor_frame.h>

#include <gtest/gtest.h>

#include <cmath>

using mrpt::poses::CPose2D;

TEST(SensorFrame, MotionRoundTripsAndIsIdentityForACentredSensor)
{
  const CPose2D s(0.4, -0.1, 0.3), q(1.0, 0.2, -0.4);
  const CPose2D back = swslam::geometry::sensorMotion(s, swslam::geometry::vehicleMotion(s, q));
  EXPECT_NEAR((back - q).norm(), 0, 1e-12);
  EXPECT_NEAR(back.phi(), q.phi(), 1e-12);
  const CPose2D same = swslam::geometry::vehicleMotion(CPose2D(), q);
  EXPECT_NEAR((same - q).norm(), 0, 1e-12);
}

TEST(SensorFrame, CovarianceJacobianMatchesNumeric)
{
  const CPose2D s(0.4, -0.1, 0.3), q(1.0, 0.2, -0.4);
  Eigen::Matrix3d J;
  for (int k = 0; k < 3; k++)
  {
    const double h = 1e-6;
    double dp[3] = {0, 0, 0};
    dp[k] = h;
    const CPose2D qp(q.x() + dp[0], q.y() + dp[1], q.phi() + dp[2]);
    const CPose2D qm(q.x() - dp[0], q.y() - dp[1], q.phi() - dp[2]);
    const CPose2D mp = swslam::geometry::vehicleMotion(s, qp), mm = swslam::geometry::vehicleMotion(s, qm);
    J.col(k) << (mp.x() - mm.x()) / (2 * h), (mp.y() - mm.y()) / (2 * h),
        std::remainder(mp.phi() - mm.phi(), 2 * M_PI) / (2 * h);
  }
  Eigen::Matrix3d cov;
  cov << 0.01, 0.002, 0.001, 0.002, 0.02, -0.001, 0.001, -0.001, 0.005;
  const Eigen::Matrix3d expected = J * cov * J.transpose();
  const Eigen::Matrix3d got = swslam::geometry::vehicleMotionCovariance(s, q, cov);
  EXPECT_LT((got - expected).norm(), 1e-8) << got << "\n" << expected;
}

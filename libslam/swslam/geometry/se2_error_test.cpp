// The SE(2) edge residual: zero at the truth, angle wrapping, analytic Jacobians equal to
// numeric ones (also across the +-pi seam).
#include <swslam/geometry/se2_error.h>

#include <mrpt/poses/CPose2D.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using swslam::geometry::Pose2;

TEST(Se2Error, ZeroWhenTheMeasurementIsTheRelativePose)
{
  const Pose2 a(1.0, -2.0, 3.0), b(-4.0, 0.5, -2.9);
  const Pose2 z = swslam::geometry::relativePose(a, b);
  EXPECT_LT(swslam::geometry::se2Error(a, b, z).norm(), 1e-12);
  // relativePose agrees with MRPT's pose difference b (-) a.
  const mrpt::poses::CPose2D m = mrpt::poses::CPose2D(b.x(), b.y(), b.z()) -
                                 mrpt::poses::CPose2D(a.x(), a.y(), a.z());
  EXPECT_NEAR(z.x(), m.x(), 1e-12);
  EXPECT_NEAR(z.y(), m.y(), 1e-12);
  EXPECT_NEAR(z.z(), m.phi(), 1e-12);
  EXPECT_LT((swslam::geometry::composePose(a, z) - b).norm(), 1e-12);
}

TEST(Se2Error, AngleErrorIsWrapped)
{
  // theta_j - theta_i - theta_z = 3.1 - (-3.1) - 0 = 6.2 rad, i.e. -0.083 rad.
  const Eigen::Vector3d e = swslam::geometry::se2Error(Pose2(0, 0, -3.1), Pose2(0, 0, 3.1), Pose2::Zero());
  EXPECT_NEAR(e.z(), 6.2 - 2 * M_PI, 1e-12);
  EXPECT_NEAR(swslam::geometry::wrapAngle(M_PI + 0.1), -M_PI + 0.1, 1e-12);
}

TEST(Se2Error, AnalyticJacobiansMatchNumericOnes)
{
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> pos(-10, 10), ang(-M_PI, M_PI);
  for (int trial = 0; trial < 200; ++trial)
  {
    const Pose2 xi(pos(rng), pos(rng), ang(rng)), xj(pos(rng), pos(rng), ang(rng));
    const Pose2 z(pos(rng) * 0.1, pos(rng) * 0.1, ang(rng));
    Eigen::Matrix3d Ji, Jj;
    const Eigen::Vector3d e = swslam::geometry::se2ErrorWithJacobians(xi, xj, z, Ji, Jj);
    const double h = 1e-6;
    for (int k = 0; k < 3; ++k)
    {
      Pose2 d = Pose2::Zero();
      d[k] = h;
      auto diff = [&](const Eigen::Vector3d& ep, const Eigen::Vector3d& em) {
        Eigen::Vector3d v = (ep - em) / (2 * h);
        v.z() = swslam::geometry::wrapAngle(ep.z() - em.z()) / (2 * h);  // across the seam
        return v;
      };
      const Eigen::Vector3d ni = diff(swslam::geometry::se2Error(xi + d, xj, z), swslam::geometry::se2Error(xi - d, xj, z));
      const Eigen::Vector3d nj = diff(swslam::geometry::se2Error(xi, xj + d, z), swslam::geometry::se2Error(xi, xj - d, z));
      EXPECT_LT((Ji.col(k) - ni).norm(), 1e-6) << "trial " << trial << " column " << k;
      EXPECT_LT((Jj.col(k) - nj).norm(), 1e-6) << "trial " << trial << " column " << k;
    }
    EXPECT_LT((e - swslam::geometry::se2Error(xi, xj, z)).norm(), 1e-15);
  }
}

TEST(Se2Error, GivenSinCosGivesExactlyTheSameResidualAndJacobians)
{
  // The optimizer's form (sin/cos computed once per pose and per measurement) against the
  // plain one: bit for bit, so that sharing them changes no result.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-50, 50), ang(-M_PI, M_PI);
  for (int trial = 0; trial < 100; ++trial)
  {
    const Pose2 xi(pos(rng), pos(rng), ang(rng)), xj(pos(rng), pos(rng), ang(rng));
    const Pose2 z(pos(rng) * 0.1, pos(rng) * 0.1, ang(rng));
    const swslam::geometry::SinCos ri = swslam::geometry::sinCos(xi.z()), rz = swslam::geometry::sinCos(z.z());
    EXPECT_EQ(ri.c, std::cos(xi.z()));
    EXPECT_EQ(ri.s, std::sin(xi.z()));
    Eigen::Matrix3d Ji, Jj, Ki, Kj;
    const Eigen::Vector3d e = swslam::geometry::se2ErrorWithJacobians(xi, xj, z, Ji, Jj);
    const Eigen::Vector3d f = swslam::geometry::se2ErrorWithJacobians(xi, xj, z, ri, rz, Ki, Kj);
    EXPECT_EQ(e, f);
    EXPECT_EQ(Ji, Ki);
    EXPECT_EQ(Jj, Kj);
    EXPECT_EQ(swslam::geometry::se2Error(xi, xj, z, ri, rz), swslam::geometry::se2Error(xi, xj, z));
  }
}

// Pairwise consistency of loop edges: the cycle error against a composition by homogeneous
// matrices, zero for agreeing loops, and the chi-square by hand.
#include <swslam/loop/consistency.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>

using namespace swslam;
using namespace swslam::loop;
using mrpt::poses::CPose2D;

namespace
{
Eigen::Matrix3d H(const CPose2D& p)
{
  Eigen::Matrix3d m;
  m << std::cos(p.phi()), -std::sin(p.phi()), p.x(), std::sin(p.phi()), std::cos(p.phi()), p.y(), 0, 0, 1;
  return m;
}
}  // namespace

TEST(LoopPairError, MatchesHomogeneousMatricesAndVanishesForAgreeingLoops)
{
  const CPose2D xa(1, 2, 0.3), xb(2.5, 2.2, 0.5), xn(3, 1, 2.9), xm(4.2, 0.4, -3.0);
  const CPose2D rel_ab = xb - xa, rel_nm = xm - xn;
  const CPose2D z1 = xn - xa, z2 = xm - xb;
  EXPECT_LT(loopPairError(z1, z2, rel_ab, rel_nm).norm(), 1e-12);

  const CPose2D z2_bad = z2 + CPose2D(0.4, -0.3, 0.1);
  const Eigen::Vector3d e = loopPairError(z1, z2_bad, rel_ab, rel_nm);
  const Eigen::Matrix3d slow = (H(z1) * H(rel_nm)).inverse() * (H(rel_ab) * H(z2_bad));
  EXPECT_NEAR(e.x(), slow(0, 2), 1e-12);
  EXPECT_NEAR(e.y(), slow(1, 2), 1e-12);
  EXPECT_NEAR(e.z(), std::atan2(slow(1, 0), slow(0, 0)), 1e-12);
}

TEST(LoopPairChi2, HandComputedValue)
{
  // Identity graph stretches, loops 0.5 m apart along a rotated direction: e = (0.3, 0.4, 0.1).
  LoopEdgeMeasure l1, l2;
  l1.z = CPose2D(2, 0, 0);
  l2.z = CPose2D(2.3, 0.4, 0.1);
  l1.covariance = Eigen::Vector3d(0.01, 0.04, 0.001).asDiagonal();  // largest xy: 0.04
  l2.covariance = Eigen::Vector3d(0.03, 0.02, 0.002).asDiagonal();  // largest xy: 0.03
  const double chi2 = loopPairChi2(l1, l2, CPose2D(), CPose2D(), 0.3, 0.1);
  // v_xy = 0.04 + 0.03 + 0.09 = 0.16, v_th = 0.003 + 0.01 = 0.013
  EXPECT_NEAR(chi2, 0.25 / 0.16 + 0.01 / 0.013, 1e-9);
  // No variance at all: no bound, infinity rather than a division by zero.
  const LoopEdgeMeasure exact1{0, 1, l1.z, Eigen::Matrix3d::Zero()}, exact2{0, 1, l2.z, Eigen::Matrix3d::Zero()};
  EXPECT_TRUE(std::isinf(loopPairChi2(exact1, exact2, CPose2D(), CPose2D(), 0, 0)));
}

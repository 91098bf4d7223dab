// A scan between two keyframes, from its match and the keyframes' motion (placement.h).
#include <swslam/tracking/placement.h>

#include <swslam/geometry/expect_pose.h>
#include <swslam/geometry/se2_scaling.h>

#include <Eigen/QR>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace swslam;
using namespace swslam::tracking;
using mrpt::poses::CPose2D;
using swslam::geometry::expectPose;

namespace
{

/** The slow version: the two estimates as whitened rows of one least-squares problem,
 * solved by QR, the angle's difference taken at the interpolation. */
CPose2D stackedLeastSquares(const CPose2D& b_from_a, double t, double T, const CPose2D& match,
                            const Eigen::Matrix3d& information, const PlacementModel& model)
{
  const CPose2D i = geometry::scaledMotion(b_from_a, t / T);
  const double sxy = model.acceleration * t * (T - t) / 2, sth = model.angular_acceleration * t * (T - t) / 2;
  Eigen::Matrix<double, 6, 3> A;
  Eigen::Matrix<double, 6, 1> rhs;
  const Eigen::Matrix3d Lm = Eigen::LLT<Eigen::Matrix3d>(information).matrixU();
  const Eigen::Vector3d z(match.x() - i.x(), match.y() - i.y(), std::remainder(match.phi() - i.phi(), 2 * M_PI));
  A.topRows<3>() = Lm;
  rhs.head<3>() = Lm * z;
  A.bottomRows<3>() = Eigen::Vector3d(1 / sxy, 1 / sxy, 1 / sth).asDiagonal();
  rhs.tail<3>().setZero();
  const Eigen::Vector3d d = A.colPivHouseholderQr().solve(rhs);
  return CPose2D(i.x() + d.x(), i.y() + d.y(), i.phi() + d.z());
}
}  // namespace

TEST(Placement, AnUnmatchedScanLiesOnTheKeyframesMotionAtConstantVelocity)
{
  const CPose2D b(0.8, 0.1, 0.3), match(0.05, -0.2, 0.4);
  for (double t : {0.01, 0.1, 0.25, 0.39})
    expectPose(placeBetweenKeyframes(b, t, 0.4, match, Eigen::Matrix3d::Zero(), PlacementModel{}),
               geometry::scaledMotion(b, t / 0.4), 1e-12, "no information");
}

TEST(Placement, AnInformationThatIsNotFiniteCountsAsNone)
{
  const CPose2D b(0.8, 0.1, 0.3), match(0.05, -0.2, 0.4);
  Eigen::Matrix3d info = Eigen::Matrix3d::Identity();
  info(0, 1) = info(1, 0) = std::numeric_limits<double>::quiet_NaN();
  expectPose(placeBetweenKeyframes(b, 0.1, 0.4, match, info, PlacementModel{}), geometry::scaledMotion(b, 0.25), 1e-12,
             "NaN");
  info = Eigen::Vector3d(std::numeric_limits<double>::infinity(), 1, 1).asDiagonal();
  expectPose(placeBetweenKeyframes(b, 0.1, 0.4, match, info, PlacementModel{}), geometry::scaledMotion(b, 0.25), 1e-12,
             "infinite");
}

TEST(Placement, AConfidentMatchKeepsItsPose)
{
  // 1 mm and 0.06 deg against the interpolation's 2.5 cm and 1.4 deg at t = 0.2 of 0.4 s.
  const CPose2D b(0.8, 0.1, 0.3), match(0.45, 0.02, 0.17);
  const Eigen::Matrix3d info = Eigen::Vector3d(1e6, 1e6, 1e6).asDiagonal();
  expectPose(placeBetweenKeyframes(b, 0.2, 0.4, match, info, PlacementModel{}), match, 2e-3, "confident match");
}

TEST(Placement, OutsideTheIntervalTheMatchAlone)
{
  const CPose2D b(0.8, 0.1, 0.3), match(0.45, 0.02, 0.17);
  for (double t : {-0.1, 0.0, 0.4, 0.5})
    expectPose(placeBetweenKeyframes(b, t, 0.4, match, Eigen::Matrix3d::Zero(), PlacementModel{}), match, 0,
               "outside");
  expectPose(placeBetweenKeyframes(b, 0.1, 0.0, match, Eigen::Matrix3d::Zero(), PlacementModel{}), match, 0,
             "no interval");
}

TEST(Placement, AlongADirectionTheMatchDoesNotInformTheKeyframesDecide)
{
  // Between walls along x, with no trunk to fix the motion along them: the match slid back
  // 0.2 m along x (weak), and is right across (y) and in heading.
  const CPose2D b(1.0, 0.0, 0.0);
  const CPose2D match(0.3, 0.01, 0.005);
  const Eigen::Matrix3d info = Eigen::Vector3d(1e-2, 1e5, 1e6).asDiagonal();
  const CPose2D p = placeBetweenKeyframes(b, 0.25, 0.5, match, info, PlacementModel{});
  EXPECT_NEAR(p.x(), 0.5, 1e-3);   // the keyframes' constant motion
  EXPECT_NEAR(p.y(), 0.01, 1e-3);  // the match
  EXPECT_NEAR(p.phi(), 0.005, 1e-3);
}

TEST(Placement, AgreesWithTheStackedLeastSquaresOfBoth)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 200; k++)
  {
    const double T = 0.05 + 2 * std::abs(u(rng)), t = T * (0.5 + 0.49 * u(rng));
    const CPose2D b(2 * u(rng), u(rng), 3 * u(rng));
    const CPose2D i = geometry::scaledMotion(b, t / T);
    const CPose2D match(i.x() + 0.3 * u(rng), i.y() + 0.3 * u(rng), i.phi() + 0.2 * u(rng));
    Eigen::Matrix3d R = Eigen::Matrix3d::Random();
    const Eigen::Matrix3d info = R * Eigen::Vector3d(std::pow(10, 6 * std::abs(u(rng))), 1e4 * std::abs(u(rng)) + 1e-3,
                                                     std::pow(10, 5 * u(rng)))
                                         .asDiagonal() *
                                     R.transpose() +
                                 1e-9 * Eigen::Matrix3d::Identity();
    const PlacementModel model{0.2 + 3 * std::abs(u(rng)), 0.1 + 2 * std::abs(u(rng))};
    expectPose(placeBetweenKeyframes(b, t, T, match, info, model), stackedLeastSquares(b, t, T, match, info, model),
               1e-7, "against the stacked least squares");
  }
}

TEST(Placement, HeadingsAcrossPiAreAveragedTheShortWay)
{
  // A turn of 3.1 rad between the keyframes; the scan near its end, matched at -3.13 rad: the
  // interpolation (3.038) and the match lie on either side of +-pi, 0.115 rad apart.
  const CPose2D b(0.0, 0.0, 3.1);
  const double T = 1.0, t = 0.98;
  const PlacementModel model{1.0, 60 * M_PI / 180};
  const CPose2D i = geometry::scaledMotion(b, t / T);
  const CPose2D match(i.x(), i.y(), -3.13);
  const double sth = model.angular_acceleration * t * (T - t) / 2;  // equal weights in heading
  const Eigen::Matrix3d info = Eigen::Vector3d(1e6, 1e6, 1 / (sth * sth)).asDiagonal();
  const CPose2D p = placeBetweenKeyframes(b, t, T, match, info, model);
  EXPECT_NEAR(std::remainder(p.phi() - i.phi(), 2 * M_PI), 0.5 * std::remainder(-3.13 - i.phi(), 2 * M_PI), 1e-9);
  EXPECT_GT(std::abs(p.phi()), 3.0);
}

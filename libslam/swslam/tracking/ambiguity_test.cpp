// Weak directions of a match and the prior taken along them, against closed forms and a slow
// version that inverts the covariance.
#include <swslam/tracking/ambiguity.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace swslam::tracking;

namespace
{
/** The slow version: invert the covariance, normalize it, and compare every eigenvalue with the
 * largest. Returns the weakest / strongest ratio and the weak directions' count. */
std::pair<double, int> slowWeak(const Eigen::Matrix3d& cov, double length, double threshold)
{
  const Eigen::Matrix3d S = Eigen::Vector3d(1, 1, length).asDiagonal();
  const Eigen::Matrix3d info = S.inverse() * cov.inverse() * S.inverse();
  const Eigen::Vector3d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(info).eigenvalues();
  int weak = 0;
  for (int k = 0; k < 3; k++) weak += l(k) / l(2) < threshold ? 1 : 0;
  return {l(0) / l(2), weak};
}

Eigen::Matrix3d randomCovariance(std::mt19937& rng)
{
  std::normal_distribution<double> n;
  Eigen::Matrix3d A;
  for (int i = 0; i < 9; i++) A(i) = n(rng);
  const Eigen::Matrix3d Q = Eigen::HouseholderQR<Eigen::Matrix3d>(A).householderQ();
  std::uniform_real_distribution<double> logv(-5, 0);
  const Eigen::Vector3d v(std::pow(10, logv(rng)), std::pow(10, logv(rng)), std::pow(10, logv(rng)));
  return Q * v.asDiagonal() * Q.transpose();
}
}  // namespace

TEST(Ambiguity, ThresholdIsWhatNoiseFakesTimesTheFactor)
{
  // 3 cm noise on a 0.2 m segment tilts its normal by sqrt(2) 0.03 / 0.2 rad: 0.045 of a
  // point's information goes to the direction across it.
  EXPECT_NEAR(weakRatioThreshold(0.03 * 0.03, 0.2, 1), 0.045, 1e-12);
  EXPECT_NEAR(weakRatioThreshold(2 * 0.03 * 0.03, 0.2, 2), 0.18, 1e-12);
  EXPECT_EQ(weakRatioThreshold(1.0, 0.2, 1), 0.5) << "clamped";
  EXPECT_EQ(weakRatioThreshold(0.03 * 0.03, 0, 1), 0) << "no segment length: nothing to derive";
  EXPECT_EQ(weakRatioThreshold(0.03 * 0.03, 0.2, 0), 0) << "off";
  EXPECT_EQ(weakRatioThreshold(0, 0.2, 1), 0) << "no noise";
  EXPECT_EQ(weakRatioThreshold(std::nan(""), 0.2, 1), 0);
  // 23 residuals of 2 cm rms less three fitted parameters.
  EXPECT_NEAR(residualNoiseVariance(20 * 0.02 * 0.02, 23, 1.0), 0.02 * 0.02, 1e-15);
  EXPECT_EQ(residualNoiseVariance(5.0, 3, 0.5), 0.5) << "no degree of freedom";
  EXPECT_EQ(residualNoiseVariance(0.0, 0, 0.5), 0.5);
}

TEST(Ambiguity, RotationLengthIsTheRootMeanSquareRange)
{
  EXPECT_NEAR(rotationLength({{3, 4}, {0, 5}}), 5, 1e-12);
  EXPECT_NEAR(rotationLength({{1, 0}, {0, 7}}), 5, 1e-12);
  EXPECT_EQ(rotationLength({}), 1) << "no points";
  EXPECT_EQ(rotationLength({{0, 0}}), 1) << "all at the sensor";
}

TEST(Ambiguity, AgreesWithTheInverseOfTheCovariance)
{
  std::mt19937 rng(3);
  for (int trial = 0; trial < 500; trial++)
  {
    const Eigen::Matrix3d cov = randomCovariance(rng);
    const double length = 0.5 + trial % 7;
    const Ambiguity a = findWeakDirections(cov, length, 0.01);
    const auto [ratio, weak] = slowWeak(cov, length, 0.01);
    ASSERT_NEAR(std::log(a.ratio), std::log(ratio), 1e-4) << "trial " << trial;
    // An eigenvalue within round-off of the threshold may go either way.
    if (std::abs(std::log(ratio / 0.01)) > 1e-4) ASSERT_EQ(a.weak, weak) << "trial " << trial;
    // The weak directions are unit eigenvectors of the normalized information.
    const Eigen::Matrix3d S = Eigen::Vector3d(1, 1, length).asDiagonal();
    const Eigen::Matrix3d info = S.inverse() * cov.inverse() * S.inverse();
    for (int k = 0; k < a.weak; k++)
    {
      const Eigen::Vector3d v = a.directions.col(k);
      ASSERT_NEAR(v.norm(), 1, 1e-9);
      const Eigen::Vector3d iv = info * v;
      ASSERT_LT((iv - v.dot(iv) * v).norm(), 1e-6 * info.norm()) << "trial " << trial;
    }
  }
}

TEST(Ambiguity, ACorridorsAxisIsWeakAndOnlyIt)
{
  // Along x the variance is 100 times the cross-axis one: information ratio 0.01.
  const Eigen::Matrix3d cov = Eigen::Vector3d(1e-2, 1e-4, 1e-5).asDiagonal();
  const Ambiguity a = findWeakDirections(cov, 3.0, 0.09);
  ASSERT_EQ(a.weak, 1);
  EXPECT_NEAR(std::abs(a.directions(0, 0)), 1, 1e-12);
  EXPECT_EQ(findWeakDirections(cov, 3.0, 0.005).weak, 0) << "below the threshold's own ratio";
}

TEST(Ambiguity, ABadCovarianceHasEveryDirectionWeak)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(findWeakDirections(Eigen::Matrix3d::Constant(nan), 1, 0.1).weak, 3);
  EXPECT_EQ(findWeakDirections(Eigen::Matrix3d::Zero(), 1, 0.1).weak, 3);
  EXPECT_EQ(findWeakDirections(-Eigen::Matrix3d::Identity(), 1, 0.1).weak, 3);
  EXPECT_EQ(findWeakDirections(Eigen::Matrix3d::Identity(), 0, 0.1).weak, 3);
}

TEST(Ambiguity, ThePriorDecidesAlongTheWeakDirectionOnly)
{
  // A wall along x: x is weak. The prior's x replaces the match's, y and theta stay.
  const Eigen::Matrix3d cov0 = Eigen::Vector3d(1e6, 1e-4, 1e-5).asDiagonal();
  const Ambiguity a = findWeakDirections(cov0, 4.0, 0.09);
  ASSERT_EQ(a.weak, 1);
  Eigen::Vector3d pose(2.0, 0.3, 0.1);
  Eigen::Matrix3d cov = cov0;
  const Eigen::Matrix3d prior_cov = Eigen::Vector3d(1.0, 1.0, 0.03).asDiagonal();
  takePriorAlongWeak(pose, cov, Eigen::Vector3d(0.5, 0.0, 2 * M_PI + 0.05), prior_cov, a, 4.0);
  EXPECT_NEAR(pose.x(), 0.5, 1e-12);
  EXPECT_NEAR(pose.y(), 0.3, 1e-9);
  EXPECT_NEAR(pose.z(), 0.1, 1e-9);
  EXPECT_NEAR(cov(0, 0), 1.0, 1e-6) << "the prior's variance along the axis";
  EXPECT_NEAR(cov(1, 1), 1e-4, 1e-12);
  EXPECT_NEAR(cov(2, 2), 1e-5, 1e-12);

  // A weak direction mixing x and theta (normalized u = [x, y, L theta]): the pose moves by
  // the prior's difference projected on it, in those units.
  Ambiguity m;
  m.weak = 1;
  m.directions.col(0) = Eigen::Vector3d(1, 0, 1).normalized();
  Eigen::Vector3d p(0, 0, 0);
  Eigen::Matrix3d c = Eigen::Matrix3d::Identity() * 1e-4;
  takePriorAlongWeak(p, c, Eigen::Vector3d(1.0, 5.0, 0.0), Eigen::Matrix3d::Zero(), m, 2.0);
  // An exact prior: d = [1, 5, 0] -> u = [1, 5, 0]; along v: 1 / sqrt(2) -> shift u
  // [0.5, 0, 0.5] -> theta 0.25.
  EXPECT_NEAR(p.x(), 0.5, 1e-12);
  EXPECT_NEAR(p.y(), 0.0, 1e-12);
  EXPECT_NEAR(p.z(), 0.25, 1e-12);

  // No weak direction: nothing changes.
  Eigen::Vector3d q(1, 2, 3);
  Eigen::Matrix3d cq = Eigen::Matrix3d::Identity();
  takePriorAlongWeak(q, cq, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), Ambiguity(), 1);
  EXPECT_EQ(q, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(cq, Eigen::Matrix3d::Identity());
}

TEST(Ambiguity, AWeakDirectionTakesThePriorsValueAndVariance)
{
  // y is weak: the match's y (variance 0.04) gives way to the prior's (variance 0.01).
  Ambiguity a;
  a.weak = 1;
  a.directions.col(0) = Eigen::Vector3d(0, 1, 0);
  Eigen::Vector3d pose(1, 2, 0.3);
  Eigen::Matrix3d cov = Eigen::Vector3d(1e-4, 0.04, 1e-5).asDiagonal();
  const Eigen::Vector3d prior(5, 1, -0.2);
  const Eigen::Matrix3d prior_cov = Eigen::Vector3d(0.01, 0.01, 0.01).asDiagonal();
  takePriorAlongWeak(pose, cov, prior, prior_cov, a, 3.0);
  EXPECT_NEAR(pose.y(), 1, 1e-12);
  EXPECT_NEAR(cov(1, 1), 0.01, 1e-12);
  EXPECT_EQ(pose.x(), 1);
  EXPECT_EQ(pose.z(), 0.3);
  EXPECT_EQ(cov(0, 0), 1e-4);
  EXPECT_EQ(cov(2, 2), 1e-5);
  // A covariance that is not finite: the prior alone.
  Eigen::Matrix3d bad = Eigen::Matrix3d::Constant(std::nan(""));
  Eigen::Vector3d p2(1, 2, 3);
  takePriorAlongWeak(p2, bad, prior, prior_cov, findWeakDirections(bad, 1, 0.1), 1.0);
  EXPECT_EQ(p2, prior);
  EXPECT_EQ(bad, prior_cov);
}

#include <swslam/eval/ate.h>

#include <mrpt/math/wrap2pi.h>

#include <gtest/gtest.h>

#include <random>

#include "eval_test_support.h"

TEST(EvalAte, RigidlyMovedTrajectoryHasZeroErrorAndTheInverseAlignment)
{
  const auto gt = swslam::test::wanderingPath(300, 50, 11);
  const mrpt::poses::CPose2D offset(-7.5, 3.0, 2.2);
  const auto moved = swslam::test::transformed(gt, offset);
  const auto r = swslam::eval::absoluteTrajectoryError(swslam::test::pairUp(moved, gt));
  EXPECT_NEAR(r.position.rmse, 0, 1e-9);
  EXPECT_NEAR(r.position.max, 0, 1e-9);
  const auto inv = -offset;
  EXPECT_NEAR(r.alignment.x(), inv.x(), 1e-9);
  EXPECT_NEAR(r.alignment.y(), inv.y(), 1e-9);
  EXPECT_NEAR(mrpt::math::wrapToPi(r.alignment.phi() - inv.phi()), 0, 1e-12);
}

TEST(EvalAte, RadialNoiseOnACircleGivesExactlyItsMagnitude)
{
  // Truth on a circle of radius 10 m, estimate on one of 10.2 m (then moved rigidly): the
  // radial errors sum to zero and have no moment, so the best alignment undoes the rigid
  // move only and every error is exactly 0.2 m.
  std::vector<swslam::common::StampedPose> gt, est;
  for (int k = 0; k < 72; k++)
  {
    const double a = 2 * M_PI * k / 72;
    gt.push_back({double(k), {10 * std::cos(a), 10 * std::sin(a), a + M_PI / 2}});
    est.push_back({double(k), {10.2 * std::cos(a), 10.2 * std::sin(a), a + M_PI / 2}});
  }
  const auto r = swslam::eval::absoluteTrajectoryError(
      swslam::test::pairUp(swslam::test::transformed(est, {4, -1, 0.4}), gt));
  EXPECT_NEAR(r.position.rmse, 0.2, 1e-9);
  EXPECT_NEAR(r.position.mean, 0.2, 1e-9);
  EXPECT_NEAR(r.position.median, 0.2, 1e-9);
  EXPECT_NEAR(r.position.max, 0.2, 1e-9);
}

TEST(EvalAte, AlignmentNeverDoesWorseThanTheIdentity)
{
  std::mt19937 rng(5);
  std::normal_distribution<double> n(0, 0.3);
  const auto gt = swslam::test::wanderingPath(100, 0, 8);
  auto est = gt;
  double sum_sq = 0;
  for (auto& p : est)
  {
    const double dx = n(rng), dy = n(rng);
    p.pose = {p.pose.x() + dx, p.pose.y() + dy, p.pose.phi()};
    sum_sq += dx * dx + dy * dy;
  }
  const auto r = swslam::eval::absoluteTrajectoryError(swslam::test::pairUp(est, gt));
  EXPECT_LE(r.position.rmse, std::sqrt(sum_sq / gt.size()));
  EXPECT_GT(r.position.rmse, 0.5 * 0.3 * std::sqrt(2.0));  // noise does not vanish
  EXPECT_THROW(swslam::eval::absoluteTrajectoryError({}), std::invalid_argument);
}

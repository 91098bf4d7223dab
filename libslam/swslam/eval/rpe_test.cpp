#include <swslam/eval/rpe.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "eval_test_support.h"

using swslam::test::homogeneous;

TEST(EvalRpe, DistancePairsMatchABruteForcePathLength)
{
  const auto gt = swslam::test::wanderingPath(120, 0, 4);
  const auto pairs = swslam::test::pairUp(gt, gt);
  for (const double d : {0.25, 1.0, 3.7})
  {
    std::vector<std::pair<size_t, size_t>> want;
    for (size_t i = 0; i < pairs.size(); i++)
      for (size_t j = i + 1; j < pairs.size(); j++)
      {
        double len = 0;
        for (size_t k = i + 1; k <= j; k++) len += pairs[k].gt.distanceTo(pairs[k - 1].gt);
        if (len >= d)
        {
          want.emplace_back(i, j);
          break;
        }
      }
    const auto got = swslam::eval::distancePairs(pairs, d);
    ASSERT_EQ(got.size(), want.size()) << d;
    for (size_t k = 0; k < want.size(); k++)
    {
      EXPECT_EQ(got[k].i, want[k].first);
      EXPECT_EQ(got[k].j, want[k].second);
    }
  }
  EXPECT_EQ(swslam::eval::consecutivePairs(4).size(), 3u);
  EXPECT_TRUE(swslam::eval::consecutivePairs(1).empty());
}

TEST(EvalRpe, EqualsTheMatrixFormulaOnNoisyPoses)
{
  std::mt19937 rng(9);
  std::normal_distribution<double> n(0, 0.05);
  const auto gt = swslam::test::wanderingPath(80, 0, 12);
  auto est = swslam::test::transformed(gt, {1, 2, 0.5});  // RPE ignores a global offset
  for (auto& p : est) p.pose = {p.pose.x() + n(rng), p.pose.y() + n(rng), p.pose.phi() + n(rng)};
  const auto pairs = swslam::test::pairUp(est, gt);
  const auto segments = swslam::eval::distancePairs(pairs, 1.0);
  double sum_t = 0, sum_r = 0;
  size_t within = 0;
  for (const auto& [i, j] : segments)
  {
    // Sturm et al. eq. 3: E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j).
    const Eigen::Matrix3d E =
        (homogeneous(gt[i].pose).inverse() * homogeneous(gt[j].pose)).inverse() *
        (homogeneous(est[i].pose).inverse() * homogeneous(est[j].pose));
    sum_t += std::pow(swslam::test::transNorm(E), 2);
    within += swslam::test::transNorm(E) < 0.05 ? 1 : 0;
    sum_r += std::pow(swslam::test::rotAngle(E), 2);
  }
  const auto r = swslam::eval::relativePoseError(pairs, segments);
  ASSERT_EQ(r.translation.n, segments.size());
  EXPECT_NEAR(r.translation.rmse, std::sqrt(sum_t / segments.size()), 1e-12);
  EXPECT_NEAR(r.rotation.rmse, std::sqrt(sum_r / segments.size()), 1e-12);
  EXPECT_GT(r.translation.rmse, 0.01);
  EXPECT_DOUBLE_EQ(r.share_within_5cm, within / static_cast<double>(segments.size()));
  EXPECT_GT(within, 0u);
  EXPECT_LT(within, segments.size());
  EXPECT_TRUE(std::isnan(swslam::eval::relativePoseError(pairs, {}).share_within_5cm));
}

TEST(EvalRpe, RigidOffsetIsZeroAndScaleErrorIsItsClosedForm)
{
  const auto gt = swslam::test::wanderingPath(100, 0, 2);
  const auto moved = swslam::test::transformed(gt, {-3, 8, -1.0});
  const auto pairs = swslam::test::pairUp(moved, gt);
  const auto r = swslam::eval::relativePoseError(pairs, swslam::eval::consecutivePairs(100));
  EXPECT_NEAR(r.translation.max, 0, 1e-9);
  EXPECT_NEAR(r.rotation.max, 0, 1e-9);

  // Straight line, 0.5 m steps; the estimate moves 0.55 m per step: every consecutive pair
  // is 0.05 m off, every 1 m segment (two steps) 0.1 m.
  std::vector<swslam::common::StampedPose> line, stretched;
  for (int k = 0; k < 20; k++)
  {
    line.push_back({0.1 * k, {0.5 * k, 0, 0}});
    stretched.push_back({0.1 * k, {0.55 * k, 0, 0}});
  }
  const auto lp = swslam::test::pairUp(stretched, line);
  const auto step = swslam::eval::relativePoseError(lp, swslam::eval::consecutivePairs(20));
  EXPECT_NEAR(step.translation.rmse, 0.05, 1e-12);
  const auto seg = swslam::eval::relativePoseError(lp, swslam::eval::distancePairs(lp, 1.0));
  EXPECT_EQ(seg.translation.n, 18u);
  EXPECT_NEAR(seg.translation.rmse, 0.1, 1e-12);
  EXPECT_NEAR(seg.rotation.rmse, 0, 1e-12);
}

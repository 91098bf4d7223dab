#include <swslam/eval/association.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "eval_test_support.h"

using swslam::common::StampedPose;

namespace
{
// The TUM associate.py algorithm, literally: all pairs, sorted by |dt|, taken greedily.
std::vector<std::pair<double, double>> slowAssociate(const std::vector<swslam::common::StampedPose>& est,
                                                     const std::vector<swslam::common::StampedPose>& gt,
                                                     double max_dt)
{
  std::vector<std::tuple<double, size_t, size_t>> all;
  for (size_t i = 0; i < est.size(); i++)
    for (size_t j = 0; j < gt.size(); j++)
      if (std::abs(est[i].t - gt[j].t) <= max_dt)
        all.emplace_back(std::abs(est[i].t - gt[j].t), i, j);
  std::stable_sort(all.begin(), all.end(),
                   [](const auto& a, const auto& b) { return std::get<0>(a) < std::get<0>(b); });
  std::vector<bool> ue(est.size()), ug(gt.size());
  std::vector<std::pair<double, double>> out;
  for (const auto& [dt, i, j] : all)
    if (!ue[i] && !ug[j])
    {
      ue[i] = ug[j] = true;
      out.emplace_back(est[i].t, gt[j].t);
    }
  std::sort(out.begin(), out.end(), [](auto a, auto b) { return a.second < b.second; });
  return out;
}
}  // namespace

TEST(EvalAssociation, MatchesTheBruteForceGreedyAssociation)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  std::bernoulli_distribution drop(0.15);
  for (int trial = 0; trial < 20; trial++)
  {
    const auto gt = swslam::test::wanderingPath(200, 1000.0, trial);
    std::vector<swslam::common::StampedPose> est;
    for (const auto& p : gt)
      if (!drop(rng)) est.push_back({p.t + jitter(rng), p.pose});
    std::shuffle(est.begin(), est.end(), rng);  // input order must not matter
    const auto a = swslam::eval::associate(est, gt, 0.01);
    const auto slow = slowAssociate(est, gt, 0.01);
    ASSERT_EQ(a.pairs.size(), slow.size());
    for (size_t k = 0; k < slow.size(); k++)
    {
      EXPECT_EQ(a.pairs[k].t_est, slow[k].first);
      EXPECT_EQ(a.pairs[k].t_gt, slow[k].second);
    }
    EXPECT_EQ(a.est_unmatched, est.size() - slow.size());
    EXPECT_EQ(a.gt_unmatched, gt.size() - slow.size());
  }
}

TEST(EvalAssociation, EachStampIsUsedOnceAndPosesTravelWithTheirStamps)
{
  const std::vector<swslam::common::StampedPose> gt{{1.0, {1, 0, 0}}, {1.004, {2, 0, 0}}, {2.0, {3, 0, 0}}};
  const std::vector<swslam::common::StampedPose> est{{1.003, {10, 0, 0}}, {5.0, {20, 0, 0}}};
  const auto a = swslam::eval::associate(est, gt, 0.01);
  ASSERT_EQ(a.pairs.size(), 1u);
  EXPECT_EQ(a.pairs[0].t_gt, 1.004);  // the closer of the two candidates
  EXPECT_EQ(a.pairs[0].gt.x(), 2);
  EXPECT_EQ(a.pairs[0].est.x(), 10);
  EXPECT_EQ(a.est_unmatched, 1u);
  EXPECT_EQ(a.gt_unmatched, 2u);
  EXPECT_THROW(swslam::eval::associate(est, gt, -1), std::invalid_argument);
}

TEST(EvalAssociation, ClosestInTimeMatchesALinearScan)
{
  const auto poses = swslam::test::wanderingPath(50, 0.0, 3);
  for (double t = -0.2; t < 5.2; t += 0.0137)
  {
    const auto got = swslam::eval::closestInTime(poses, t, 0.03);
    std::optional<size_t> want;
    for (size_t i = 0; i < poses.size(); i++)
      if (std::abs(poses[i].t - t) <= 0.03 &&
          (!want || std::abs(poses[i].t - t) < std::abs(poses[*want].t - t)))
        want = i;
    EXPECT_EQ(got, want) << "t=" << t;
  }
}

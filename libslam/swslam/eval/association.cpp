#include <swslam/eval/association.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace swslam::eval
{
std::vector<common::StampedPose> sortedByTime(std::vector<common::StampedPose> poses)
{
  std::stable_sort(poses.begin(), poses.end(),
                   [](const common::StampedPose& a, const common::StampedPose& b) { return a.t < b.t; });
  return poses;
}

std::optional<size_t> closestInTime(const std::vector<common::StampedPose>& sorted, double t,
                                    double max_dt)
{
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), t,
                                   [](const common::StampedPose& p, double v) { return p.t < v; });
  std::optional<size_t> best;
  double best_dt = 0;
  for (auto c = it == sorted.begin() ? it : it - 1; c != sorted.end() && c <= it; ++c)
  {
    const double dt = std::abs(c->t - t);
    if (dt <= max_dt && (!best || dt < best_dt))
    {
      best = c - sorted.begin();
      best_dt = dt;
    }
  }
  return best;
}

namespace
{
/** `poses` if they are in time order already (a run's trajectory, a TUM file), else a sorted
 * copy kept in `sorted`: a long run's trajectory is not copied twice. */
const std::vector<common::StampedPose>& inTimeOrder(const std::vector<common::StampedPose>& poses,
                                                    std::vector<common::StampedPose>& sorted)
{
  const auto earlier = [](const common::StampedPose& a, const common::StampedPose& b) { return a.t < b.t; };
  if (std::is_sorted(poses.begin(), poses.end(), earlier)) return poses;
  sorted = sortedByTime(poses);
  return sorted;
}
}  // namespace

Association associate(const std::vector<common::StampedPose>& est_in,
                      const std::vector<common::StampedPose>& gt_in, double max_dt)
{
  if (!(max_dt >= 0)) throw std::invalid_argument("associate: max_dt must be >= 0");
  std::vector<common::StampedPose> est_sorted, gt_sorted;
  const auto& est = inTimeOrder(est_in, est_sorted);
  const auto& gt = inTimeOrder(gt_in, gt_sorted);

  // Candidates (|dt|, est index, gt index): a sliding window over the sorted ground truth.
  std::vector<std::tuple<double, size_t, size_t>> candidates;
  candidates.reserve(est.size());
  size_t first = 0;
  for (size_t i = 0; i < est.size(); i++)
  {
    while (first < gt.size() && gt[first].t < est[i].t - max_dt) first++;
    for (size_t j = first; j < gt.size() && gt[j].t <= est[i].t + max_dt; j++)
      candidates.emplace_back(std::abs(gt[j].t - est[i].t), i, j);
  }
  std::sort(candidates.begin(), candidates.end());

  std::vector<bool> est_used(est.size()), gt_used(gt.size());
  Association a;
  a.pairs.reserve(std::min(est.size(), gt.size()));
  for (const auto& [dt, i, j] : candidates)
  {
    if (est_used[i] || gt_used[j]) continue;
    est_used[i] = gt_used[j] = true;
    a.pairs.push_back({est[i].t, gt[j].t, est[i].pose, gt[j].pose});
  }
  std::sort(a.pairs.begin(), a.pairs.end(),
            [](const PosePair& p, const PosePair& q) { return p.t_gt < q.t_gt; });
  a.est_unmatched = est.size() - a.pairs.size();
  a.gt_unmatched = gt.size() - a.pairs.size();
  return a;
}

}  // namespace swslam::eval

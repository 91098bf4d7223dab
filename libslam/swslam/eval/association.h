#pragma once
// Association of an estimated and a ground-truth trajectory by timestamp, as the TUM
// benchmark's associate.py: every pair of stamps closer than `max_dt` is a candidate, and
// candidates are taken greedily by increasing time difference, each stamp used once.

#include <swslam/common/tum_io.h>

#include <optional>
#include <vector>

namespace swslam::eval
{
/** One estimated pose and the ground-truth pose associated with it. */
struct PosePair
{
  double t_est = 0, t_gt = 0;  ///< seconds
  mrpt::poses::CPose2D est, gt;
};

struct Association
{
  std::vector<PosePair> pairs;  ///< sorted by ground-truth time
  size_t est_unmatched = 0;     ///< estimated poses with no ground truth within max_dt
  size_t gt_unmatched = 0;      ///< ground-truth poses with no estimate within max_dt
};

/** Associates `est` with `gt` (any order; duplicated stamps allowed) within `max_dt` seconds. */
Association associate(const std::vector<common::StampedPose>& est, const std::vector<common::StampedPose>& gt,
                      double max_dt);

/** Index of the pose of `sorted` (by increasing t) closest in time to `t`, if within max_dt. */
std::optional<size_t> closestInTime(const std::vector<common::StampedPose>& sorted, double t,
                                    double max_dt);

/** A copy of `poses` sorted by increasing time (stable). */
std::vector<common::StampedPose> sortedByTime(std::vector<common::StampedPose> poses);

}  // namespace swslam::eval

#pragma once
// Absolute trajectory error (Sturm et al., IROS 2012, eq. 1-2): position error of each
// associated pose after the best rigid SE(2) alignment of the estimate onto the truth.

#include <swslam/eval/association.h>
#include <swslam/eval/error_stats.h>

namespace swslam::eval
{
struct AteResult
{
  mrpt::poses::CPose2D alignment;  ///< S with S (+) est_i ~ gt_i
  ErrorStats position;             ///< |trans(gt_i^-1 (+) S (+) est_i)|, metres
};

/** ATE over associated poses. Throws std::invalid_argument if `pairs` is empty. */
AteResult absoluteTrajectoryError(const std::vector<PosePair>& pairs);

}  // namespace swslam::eval

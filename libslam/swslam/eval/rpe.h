#pragma once
// Relative pose error (Sturm et al., IROS 2012, eq. 3-4): for a pair of poses (i, j) the
// error of the estimated motion against the true one,
//   E_ij = (gt_i^-1 (+) gt_j)^-1 (+) (est_i^-1 (+) est_j),
// independent of any global alignment. Pairs are consecutive poses or segments of at
// least a given travelled distance along the ground truth.

#include <swslam/eval/association.h>
#include <swslam/eval/error_stats.h>
#include <swslam/geometry/sensor_frame.h>

namespace swslam::eval
{
struct IndexPair
{
  size_t i = 0, j = 0;
};

/** (0,1), (1,2), ..., (n-2, n-1). */
std::vector<IndexPair> consecutivePairs(size_t n);

/** For every i, the first j > i whose ground-truth path length from i is >= min_distance
 * (no pair for an i whose remaining path is shorter). */
std::vector<IndexPair> distancePairs(const std::vector<PosePair>& pairs, double min_distance);

/** The error of the motion a_i -> a_j against an expected motion: (a_j (-) a_i) (-) expected,
 * i.e. expected^-1 (+) a_i^-1 (+) a_j (the Kuemmerle et al. relation error too). */
mrpt::poses::CPose2D relativeError(const mrpt::poses::CPose2D& a_i,
                                   const mrpt::poses::CPose2D& a_j,
                                   const mrpt::poses::CPose2D& expected);

struct RpeResult
{
  ErrorStats translation;  ///< |trans(E_ij)|, metres
  ErrorStats rotation;     ///< |angle(E_ij)|, radians
  double share_within_5cm = 0;  ///< of the pairs, those with |trans(E_ij)| < geometry::kMotionAgreement (NaN: none)
};

/** RPE over the given pairs of indices into `pairs`. */
RpeResult relativePoseError(const std::vector<PosePair>& pairs,
                            const std::vector<IndexPair>& segments);

}  // namespace swslam::eval

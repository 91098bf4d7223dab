#pragma once
// The evaluations swslam-eval runs, and their output: "key=value" lines for scripts, then
// '#'-prefixed lines for a human reader.

#include <swslam/eval/ate.h>
#include <swslam/eval/relations.h>
#include <swslam/eval/rpe.h>

#include <string>

namespace swslam::eval
{
struct TrajectoryEvaluation
{
  size_t est_poses = 0, gt_poses = 0;
  size_t matched = 0, est_unmatched = 0, gt_unmatched = 0;
  size_t est_steps_back = 0;  ///< estimated poses stamped at or before the one before them
  double max_dt = 0, segment_length = 0;
  AteResult ate;
  RpeResult rpe_step;     ///< consecutive associated poses
  RpeResult rpe_segment;  ///< pairs >= segment_length apart along the ground truth
};

/** ATE and RPE of `est` against `gt`. Throws std::runtime_error if fewer than two poses
 * associate (naming both time spans). */
TrajectoryEvaluation evaluateTrajectory(const std::vector<common::StampedPose>& est,
                                        const std::vector<common::StampedPose>& gt, double max_dt,
                                        double segment_length = 1.0);

/** relationsError, but no usable relation is an error (naming both time spans). */
RelationsResult evaluateRelations(const std::vector<common::StampedPose>& est,
                                  const std::vector<Relation>& relations, double max_dt);

std::string formatTrajectoryEvaluation(const TrajectoryEvaluation& e);

/** What to warn when part of the estimate could not be matched by stamp, and so is not
 * scored: "scored M of the N estimated poses: K have no ground-truth pose within max_dt s",
 * with the estimate's steps back in time if it has any; "" when every pose was matched. */
std::string unmatchedWarning(const TrajectoryEvaluation& e);
std::string formatRelationsResult(const RelationsResult& r);

/** readTum, but an empty trajectory is an error naming the file. */
std::vector<common::StampedPose> readNonEmptyTum(const std::string& path);

}  // namespace swslam::eval

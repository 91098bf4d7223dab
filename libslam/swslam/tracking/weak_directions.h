#pragma once
// Where a match is ambiguous, the prediction decides (doc/tracking.md, "Ambiguous matches"): a
// converged match's weak directions (ambiguity.h), and along those that no surface of either
// scan faces (unobservable), the prior's pose and variance instead of the match's.

#include <swslam/plicp/plicp.h>
#include <swslam/tracking/keyframe.h>
#include <swslam/tracking/params.h>
#include <swslam/tracking/prepared_scan.h>

#include <mrpt/poses/CPose2D.h>

namespace swslam::tracking
{
/** How many of a match's directions were weak, and along how many of them the prior decided. */
struct WeakDirections
{
  int weak = 0, prior_decided = 0;
};

/** The weak directions of `m`, a match of `cur` against the keyframe `ref` (0 for a failed
 * match, or ambiguity_factor 0): along those of them that fewer than unobservable_min_rays rays
 * of either scan face, `m` takes `prior` (the guess it started from, sensor frame) with
 * translation variance `prior_var_xy` and rotation variance lost_prior_sigma_theta^2. Only a
 * match whose weakest direction has less than kFacingCheckRatio times the weak threshold's
 * information is tested for facing rays: the normals and the counts for every match cost
 * 0.04-0.06 ms per scan on the valley. */
WeakDirections takePriorWhereWeak(plicp::MatchResult& m, const Keyframe& ref, const PreparedScan& cur,
                                  const mrpt::poses::CPose2D& prior, double prior_var_xy, const TrackingParams& p,
                                  const plicp::PlicpParams& plicp);

}  // namespace swslam::tracking

#pragma once
// A scan between two keyframes (not a graph node itself): placed where its match to the first
// keyframe and the motion between the two keyframes agree best. A match decides where the
// scan's points do; along a direction they barely inform (a long straight between walls and
// few trunks), the keyframes' motion at constant velocity does (doc/tracking.md, "Scans
// between keyframes").

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

namespace swslam::tracking
{
/** How far a vehicle strays from constant velocity between two keyframes: a scan t seconds
 * into an interval of T lies about `acceleration` t (T - t) / 2 off the interpolation (the
 * offset of constant acceleration), its heading `angular_acceleration` t (T - t) / 2. */
struct PlacementModel
{
  double acceleration = 1.0;          ///< [m/s^2]
  double angular_acceleration = 1.0;  ///< [rad/s^2]
};

/** The pose, relative to keyframe a, of a scan taken `t` seconds after a, where the next
 * keyframe b lies at `b_from_a` (b's pose in a's frame) `interval` seconds after a, and the
 * scan's match to a gave `match` with `information` (its inverse covariance in a's vehicle
 * frame, [x, y, theta]; zero: the scan was not matched). The information-weighted mean, to
 * first order, of the match and the interpolation exp(t / T log(b_from_a)), whose standard
 * deviations follow `model` (an information that is not finite counts as none). t outside
 * (0, interval) or interval <= 0: the match. */
mrpt::poses::CPose2D placeBetweenKeyframes(const mrpt::poses::CPose2D& b_from_a, double t, double interval,
                                           const mrpt::poses::CPose2D& match, const Eigen::Matrix3d& information,
                                           const PlacementModel& model);

}  // namespace swslam::tracking

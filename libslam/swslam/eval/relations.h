#pragma once
// The relation-based metric of Kuemmerle et al., "On measuring the accuracy of SLAM
// algorithms" (Autonomous Robots 27(4), 2009), used by the Freiburg SLAM benchmark: for
// every reference relation delta*_ij between the poses at two timestamps, the error
// (x_j (-) x_i) (-) delta*_ij of the estimate, summarized by the mean and standard
// deviation of its absolute and squared translational and rotational parts.

#include <swslam/common/tum_io.h>
#include <swslam/eval/error_stats.h>

#include <string>
#include <vector>

namespace swslam::eval
{
/** One line "t1 t2 x y z roll pitch yaw" of a .relations file, projected on the plane. */
struct Relation
{
  double t1 = 0, t2 = 0;        ///< seconds
  mrpt::poses::CPose2D delta;   ///< (x, y, yaw): pose at t2 in the frame of the pose at t1
  bool planar = true;           ///< false if z, roll or pitch was not ~0 (dropped)
};

struct RelationsResult
{
  size_t used = 0;        ///< relations whose both stamps matched an estimated pose
  size_t unmatched = 0;   ///< relations with a stamp not within max_dt of any estimate
  size_t nonplanar = 0;   ///< used relations whose z, roll or pitch were dropped
  ErrorStats translation, translation_sq;  ///< m, m^2
  ErrorStats rotation, rotation_sq;        ///< rad, rad^2
};

/** Evaluates `est` (any order) against `relations`, each stamp matched to the closest
 * estimated pose within max_dt seconds. */
RelationsResult relationsError(const std::vector<common::StampedPose>& est,
                               const std::vector<Relation>& relations, double max_dt);

}  // namespace swslam::eval

#pragma once
// Whether two 2D poses differ by more than a translation or a rotation threshold: a node that
// moved enough to be re-inserted in the map (sec. IV.B), a loop that disagrees with the graph
// enough to ask for a full optimization.

#include <mrpt/core/bits_math.h>
#include <mrpt/poses/CPose2D.h>

namespace swslam::geometry
{
/** A translation and a rotation threshold; the defaults are the map's re-insertion ones. */
struct MoveThreshold
{
  double translation = 0.1;  ///< [m]
  double rotation = mrpt::DEG2RAD(0.5);  ///< [rad]
};

/** True if `b` is farther than `threshold` from `a` in translation or rotation (the rotation
 * difference wrapped to [-pi, pi]). The same as b's pose in a's frame, a^-1 (+) b, being
 * beyond the threshold: the distance does not depend on the frame. */
bool movedBeyond(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b,
                 const MoveThreshold& threshold);

}  // namespace swslam::geometry

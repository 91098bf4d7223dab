#pragma once
// A relative motion held for a different time: the same constant twist (forward, lateral and
// angular velocity). Tracking scales the last motion to the next scan interval with it; the
// scan source interpolates odometry readings to a scan's time.

#include <mrpt/poses/CPose2D.h>

namespace swslam::geometry
{
/** exp(s log(m)) in SE(2): the motion at the same constant twist held s times as long.
 * s = 1 gives m, s = 2 gives m (+) m, s = 0 the identity, s = -1 the inverse motion; any
 * real s. */
mrpt::poses::CPose2D scaledMotion(const mrpt::poses::CPose2D& m, double s);

}  // namespace swslam::geometry

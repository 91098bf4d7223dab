#pragma once
// Tracking's initial guess (doc/tracking.md): the previous motion, held at constant velocity
// over the new scan interval (scaledMotion() by intervalRatio()). Logs whose scans come at
// irregular intervals (a simulator's or a loaded computer's) would otherwise predict a 0.1 s
// step from a 0.05 s one.

#include <swslam/geometry/se2_scaling.h>

namespace swslam::tracking
{
/** dt_now / dt_prev, the scale of the previous motion for the next scan. A vehicle's velocity
 * holds for about `horizon` seconds, so the scale is exact while both intervals are within it
 * (a gap of a few dropped scans); beyond it, it is clamped to
 * [min(1 / max_ratio, dt_now / horizon), max(max_ratio, horizon / dt_prev)]: a long gap says
 * little about the motion during it. 1 if either interval is not positive (a missing or
 * repeated timestamp says nothing). */
double intervalRatio(double dt_now, double dt_prev, double max_ratio, double horizon);

}  // namespace swslam::tracking

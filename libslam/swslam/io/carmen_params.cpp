#include <swslam/io/carmen_params.h>

namespace swslam::io
{
const common::ParamTable<CarmenParams>& CarmenParams::table()
{
  using P = CarmenParams;
  using common::above, common::atLeast, common::between;
  static const auto t =
      common::ParamTable<P>("carmen", "Reading CARMEN logs (doc/carmen.md).")
          // Stored as a float in MRPT's scan: a larger value would not convert.
          .real("max_range", &P::max_range, "m", between(0, 1e6), "> 0 forces the sensor max range; 0: from the log or auto-detected")
          .real("saturation_rel_tol", &P::saturation_rel_tol, "", common::Range{0, 1, false, true},
                "auto max range: readings within this fraction below the largest...")
          .integer("saturation_min_count", &P::saturation_min_count, "", atLeast(1),
                   "...at least this many of them, mark the no-return value")
          .flag("repair_timestamps", &P::repair_timestamps, "rewrite non-increasing timestamps (previous + median period)")
          .real("max_timestamp_gap", &P::max_timestamp_gap, "s", above(0), "larger forward jumps count as timestamp problems")
          .real("default_period", &P::default_period, "s", above(0), "repair period when the log has no usable one")
          .flag("laser_only", &P::laser_only, "drop the odometry: ODOM lines, or the laser lines' odom_* fields")
          .integer("max_printed_warnings", &P::max_printed_warnings, "", atLeast(0), "printed per kind of problem; all are counted");
  return t;
}

}  // namespace swslam::io

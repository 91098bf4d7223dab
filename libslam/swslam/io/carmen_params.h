#pragma once
// How CARMEN logs are read, section [carmen] (doc/carmen.md).

#include <swslam/common/param_table.h>

#include <cstdint>

namespace swslam::io
{
/** How CARMEN logs are read, .ini section [carmen]: declared in table() (carmen_params.cpp). */
struct CarmenParams
{
  /** [m] if > 0: the maximum range of every laser, overriding the log; 0: from the line's
   * own field, else PARAM robot_*_laser_max, else saturation auto-detection. */
  double max_range = 0;
  /** Saturation cluster: readings within this fraction below the largest reading. */
  double saturation_rel_tol = 0.005;
  /** Minimum readings in the cluster for a laser to count as saturating. */
  uint64_t saturation_min_count = 5;
  /** Replace non-increasing (and jumping) timestamps by previous + median period. */
  bool repair_timestamps = true;
  /** [s] a forward step larger than this is a timestamp problem (e.g. 2^32 overflow). */
  double max_timestamp_gap = 3600;
  /** [s] repair period of a stream with no usable positive period. */
  double default_period = 0.1;
  /** Drop the odometry: ODOM lines, or the laser lines' odom_* fields of a log without them. */
  bool laser_only = false;
  /** Warnings printed per kind (malformed line, timestamp); all are counted. */
  uint64_t max_printed_warnings = 10;

  static const common::ParamTable<CarmenParams>& table();
  /** Throws std::invalid_argument naming the first key out of its range. */
  void check() const { table().check(*this); }
};

}  // namespace swslam::io

#include <swslam/io/carmen_params.h>

#include <mrpt/config/CConfigFileBase.h>

#include <stdexcept>

namespace swslam::io
{
void CarmenParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
  MRPT_LOAD_CONFIG_VAR(max_range, double, c, s);
  MRPT_LOAD_CONFIG_VAR(saturation_rel_tol, double, c, s);
  MRPT_LOAD_CONFIG_VAR(saturation_min_count, uint64_t, c, s);
  MRPT_LOAD_CONFIG_VAR(repair_timestamps, bool, c, s);
  MRPT_LOAD_CONFIG_VAR(max_timestamp_gap, double, c, s);
  MRPT_LOAD_CONFIG_VAR(default_period, double, c, s);
  MRPT_LOAD_CONFIG_VAR(laser_only, bool, c, s);
  MRPT_LOAD_CONFIG_VAR(max_printed_warnings, uint64_t, c, s);
  check();  // also when the input is a rawlog and no CARMEN log is read
}

void CarmenParams::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
  // No name padding (MRPT_SAVE_CONFIG_VAR_COMMENT pads keys, which checkKnownKeys rejects).
  c.write(s, "max_range", max_range, -1, -1, "[m] >0 forces the max range; 0: log/auto");
  c.write(s, "saturation_rel_tol", saturation_rel_tol, -1, -1, "cluster width (fraction)");
  c.write(s, "saturation_min_count", saturation_min_count, -1, -1, "readings in a cluster");
  c.write(s, "repair_timestamps", repair_timestamps, -1, -1, "strictly increasing streams");
  c.write(s, "max_timestamp_gap", max_timestamp_gap, -1, -1, "[s] larger steps: problems");
  c.write(s, "default_period", default_period, -1, -1, "[s] repair period if none in the log");
  c.write(s, "laser_only", laser_only, -1, -1, "drop the odometry: ODOM lines, or the laser lines' odom_* fields of a log without them");
  c.write(s, "max_printed_warnings", max_printed_warnings, -1, -1, "printed per kind; all counted");
}

void CarmenParams::check() const
{
  const auto fail = [](const std::string& key, const std::string& rule) {
    throw std::invalid_argument("[carmen] " + key + " must be " + rule);
  };
  // Stored as a float in MRPT's scan: a larger value would not convert.
  if (!(max_range >= 0 && max_range <= 1e6)) fail("max_range", "in [0, 1e6] m (0: from the log)");
  if (!(saturation_rel_tol >= 0 && saturation_rel_tol < 1)) fail("saturation_rel_tol", "in [0, 1)");
  if (saturation_min_count < 1) fail("saturation_min_count", ">= 1");
  if (!(max_timestamp_gap > 0)) fail("max_timestamp_gap", "> 0");
  if (!(default_period > 0)) fail("default_period", "> 0");
}
}  // namespace swslam::io

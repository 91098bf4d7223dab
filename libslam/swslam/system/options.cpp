#include <swslam/system/options.h>

#include <mrpt/config/CConfigFileBase.h>

#include <stdexcept>

namespace swslam::system
{
void SystemOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
  MRPT_LOAD_CONFIG_VAR_CS(input_queue_capacity, int);
  MRPT_LOAD_CONFIG_VAR_CS(final_full_optimization, bool);
  MRPT_LOAD_CONFIG_VAR_CS(max_printed_warnings, int);
  MRPT_LOAD_CONFIG_VAR_CS(timestamp_resume_scans, int);
  MRPT_LOAD_CONFIG_VAR_CS(max_graph_lag, int);
  MRPT_LOAD_CONFIG_VAR_CS(max_odometry_speed, double);
  if (input_queue_capacity < 1)
    throw std::invalid_argument("config [" + s + "]: input_queue_capacity must be >= 1");
  if (max_printed_warnings < 0)
    throw std::invalid_argument("config [" + s + "]: max_printed_warnings must be >= 0");
  if (timestamp_resume_scans < 0)
    throw std::invalid_argument("config [" + s + "]: timestamp_resume_scans must be >= 0");
  if (max_graph_lag < -1)
    throw std::invalid_argument("config [" + s + "]: max_graph_lag must be >= 0, or -1 for no bound");
  if (!(max_odometry_speed >= 0 && max_odometry_speed <= 1e4))
    throw std::invalid_argument("config [" + s + "]: max_odometry_speed must be in [0, 1e4] m/s (0: no check)");
}

void SystemOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
  MRPT_SAVE_CONFIG_VAR_COMMENT(input_queue_capacity, "threaded mode: scans waiting for tracking at most");
  MRPT_SAVE_CONFIG_VAR_COMMENT(final_full_optimization, "optimize the whole graph once the input ends");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_printed_warnings, "skipped-scan messages printed per kind");
  MRPT_SAVE_CONFIG_VAR_COMMENT(timestamp_resume_scans, "this many scans in order behind the last taken one resume the log (0: never)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_odometry_speed, "[m/s] a longer odometry increment (per second since the previous scan, at least one second's worth) is dropped (0: no check)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_graph_lag, "threaded mode: keyframes the graph thread has not finished at most when tracking takes a scan (-1: no bound)");
}

}  // namespace swslam::system

#include <swslam/loop/params.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/core/bits_math.h>

#include <stdexcept>
#include <string>

namespace swslam::loop
{
void LoopClosureParams::check() const
{
  auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("config [loop_closure]: ") + what);
  };
  require(consistency_window >= 0, "consistency_window must be >= 0");
  require(ambiguity_radius >= 0 && ambiguity_margin >= 0, "ambiguity_radius and ambiguity_margin must be >= 0");
  require(min_index_gap >= 1, "min_index_gap must be >= 1");
  require(std::isfinite(max_distance) && max_distance >= 0, "max_distance must be finite and >= 0");
  require(max_candidates >= 0, "max_candidates must be >= 0");
  require(min_inlier_fraction >= 0 && min_inlier_fraction <= 1,
          "min_inlier_fraction must be in [0, 1]");
  require(std::isfinite(chi2_gate) && chi2_gate > 0, "chi2_gate must be finite and > 0");
  require(std::isfinite(drift_xy_per_m) && drift_xy_per_m >= 0 &&
              std::isfinite(drift_theta_per_m) && drift_theta_per_m >= 0,
          "drift_xy_per_m and drift_theta_per_m_DEG must be finite and >= 0");
  require(std::isfinite(min_drift_sigma_xy) && min_drift_sigma_xy > 0 &&
              std::isfinite(min_drift_sigma_theta) && min_drift_sigma_theta > 0,
          "min_drift_sigma_xy and min_drift_sigma_theta_DEG must be finite and > 0");
}

void LoopClosureParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                           const std::string& s)
{
  MRPT_LOAD_CONFIG_VAR_CS(enabled, bool);
  MRPT_LOAD_CONFIG_VAR_CS(min_index_gap, int);
  MRPT_LOAD_CONFIG_VAR_CS(max_distance, double);
  MRPT_LOAD_CONFIG_VAR_CS(max_candidates, int);
  MRPT_LOAD_CONFIG_VAR_CS(min_inlier_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(chi2_gate, double);
  MRPT_LOAD_CONFIG_VAR_CS(drift_xy_per_m, double);
  drift_theta_per_m = mrpt::DEG2RAD(
      c.read_double(s, "drift_theta_per_m_DEG", mrpt::RAD2DEG(drift_theta_per_m)));
  MRPT_LOAD_CONFIG_VAR_CS(min_drift_sigma_xy, double);
  MRPT_LOAD_CONFIG_VAR_CS(consistency_window, int);
  MRPT_LOAD_CONFIG_VAR_CS(ambiguity_radius, double);
  MRPT_LOAD_CONFIG_VAR_CS(ambiguity_margin, double);
  min_drift_sigma_theta = mrpt::DEG2RAD(
      c.read_double(s, "min_drift_sigma_theta_DEG", mrpt::RAD2DEG(min_drift_sigma_theta)));
  check();
}

void LoopClosureParams::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                         const std::string& s) const
{
  MRPT_SAVE_CONFIG_VAR_COMMENT(enabled, "look for loops at each new node");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_index_gap, "a candidate is at least this many nodes older...");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_distance, "[m] ...and at most this far in the graph");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_candidates, "verified per new node, nearest first");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_inlier_fraction,
                               "fraction of the new scan's valid rays matched at the end");
  MRPT_SAVE_CONFIG_VAR_COMMENT(chi2_gate, "d^2 bound (11.34: 99 % of chi-square, 3 dof)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(drift_xy_per_m, "[m/m] drift position std per metre travelled");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("drift_theta_per_m_DEG", drift_theta_per_m,
                                       "[deg/m] drift heading std per metre travelled");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_drift_sigma_xy, "[m] floor of the drift position std");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("min_drift_sigma_theta_DEG", min_drift_sigma_theta,
                                       "[deg] floor of the drift heading std");
  MRPT_SAVE_CONFIG_VAR_COMMENT(consistency_window,
                               "a loop is an edge once another within this many node ids agrees (0: at once)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(ambiguity_radius, "[m] a loop search whose best pose farther than this from its best...");
  MRPT_SAVE_CONFIG_VAR_COMMENT(ambiguity_margin, "...scores within this of it is ambiguous: no loop");
}

}  // namespace swslam::loop

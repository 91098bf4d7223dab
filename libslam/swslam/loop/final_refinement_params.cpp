#include <swslam/loop/final_refinement_params.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/core/bits_math.h>

#include <stdexcept>
#include <string>

namespace swslam::loop
{
void FinalRefinementParams::check() const
{
  auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("config [final_refinement]: ") + what);
  };
  require(passes >= 1, "passes must be >= 1");
  require(std::isfinite(radius) && radius >= 0, "radius must be finite and >= 0");
  require(max_pairs_per_node >= 0, "max_pairs_per_node must be >= 0");
  require(min_inlier_fraction >= 0 && min_inlier_fraction <= 1,
          "min_inlier_fraction must be in [0, 1]");
  require(std::isfinite(chi2_gate) && chi2_gate > 0, "chi2_gate must be finite and > 0");
  require(std::isfinite(sigma_xy) && sigma_xy > 0 && std::isfinite(sigma_theta) && sigma_theta > 0,
          "sigma_xy and sigma_theta_DEG must be finite and > 0");
  require(std::isfinite(max_correction_xy) && max_correction_xy >= 0 &&
              std::isfinite(max_correction_theta) && max_correction_theta >= 0,
          "max_correction_xy and max_correction_theta_DEG must be finite and >= 0");
}

void FinalRefinementParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                               const std::string& s)
{
  MRPT_LOAD_CONFIG_VAR_CS(enabled, bool);
  MRPT_LOAD_CONFIG_VAR_CS(passes, int);
  MRPT_LOAD_CONFIG_VAR_CS(radius, double);
  MRPT_LOAD_CONFIG_VAR_CS(max_pairs_per_node, int);
  MRPT_LOAD_CONFIG_VAR_CS(min_inlier_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(chi2_gate, double);
  MRPT_LOAD_CONFIG_VAR_CS(sigma_xy, double);
  sigma_theta = mrpt::DEG2RAD(c.read_double(s, "sigma_theta_DEG", mrpt::RAD2DEG(sigma_theta)));
  MRPT_LOAD_CONFIG_VAR_CS(max_correction_xy, double);
  max_correction_theta = mrpt::DEG2RAD(
      c.read_double(s, "max_correction_theta_DEG", mrpt::RAD2DEG(max_correction_theta)));
  check();
}

void FinalRefinementParams::saveToConfigFile(mrpt::config::CConfigFileBase& c,
                                             const std::string& s) const
{
  MRPT_SAVE_CONFIG_VAR_COMMENT(enabled, "once the input ends, match every close unlinked pair");
  MRPT_SAVE_CONFIG_VAR_COMMENT(passes, "rounds of match, add edges, optimize the whole graph");
  MRPT_SAVE_CONFIG_VAR_COMMENT(radius, "[m] pairs at most this far apart at their optimized poses");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_pairs_per_node,
                               "each node matched with at most this many older ones, nearest first (0: all)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_inlier_fraction,
                               "fraction of the newer scan's valid rays matched at the end");
  MRPT_SAVE_CONFIG_VAR_COMMENT(chi2_gate, "d^2 bound (11.34: 99 % of chi-square, 3 dof)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(sigma_xy, "[m] position std of the optimized graph's relative pose");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("sigma_theta_DEG", sigma_theta,
                                       "[deg] heading std of the optimized graph's relative pose");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_correction_xy, "[m] the match moves the graph's guess at most this...");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("max_correction_theta_DEG", max_correction_theta,
                                       "[deg] ...and turns it at most this");
}

}  // namespace swslam::loop

#include <swslam/plicp/params.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/core/bits_math.h>

#include <stdexcept>


namespace swslam::plicp
{
void PlicpParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
  MRPT_LOAD_CONFIG_VAR_CS(max_iterations, int);
  MRPT_LOAD_CONFIG_VAR_CS(epsilon_xy, double);
  epsilon_theta = mrpt::DEG2RAD(c.read_double(s, "epsilon_theta_DEG", mrpt::RAD2DEG(epsilon_theta)));
  MRPT_LOAD_CONFIG_VAR_CS(max_correspondence_dist, double);
  MRPT_LOAD_CONFIG_VAR_CS(min_segment_length, double);
  MRPT_LOAD_CONFIG_VAR_CS(remove_doubles, bool);
  MRPT_LOAD_CONFIG_VAR_CS(trim_keep_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(adaptive_quantile, double);
  MRPT_LOAD_CONFIG_VAR_CS(adaptive_mult, double);
  MRPT_LOAD_CONFIG_VAR_CS(min_correspondences, int);
  MRPT_LOAD_CONFIG_VAR_CS(max_correction_xy, double);
  max_correction_theta = mrpt::DEG2RAD(
      c.read_double(s, "max_correction_theta_DEG", mrpt::RAD2DEG(max_correction_theta)));
  MRPT_LOAD_CONFIG_VAR_CS(range_sigma, double);
  MRPT_LOAD_CONFIG_VAR_CS(covariance_from_residuals, bool);

  auto require = [&](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("config [") + s + "]: " + what);
  };
  // A match that never settles runs to the cap, on every scan: bounded so that a run cannot stall.
  require(max_iterations >= 1 && max_iterations <= 1000, "max_iterations must be in [1, 1000]");
  require(epsilon_xy > 0 && epsilon_theta > 0, "epsilon_xy and epsilon_theta_DEG must be > 0");
  require(max_correspondence_dist > 0, "max_correspondence_dist must be > 0");
  require(min_segment_length >= 0, "min_segment_length must be >= 0");
  require(trim_keep_fraction > 0 && trim_keep_fraction <= 1, "trim_keep_fraction must be in (0, 1]");
  require(adaptive_quantile > 0 && adaptive_quantile <= 1, "adaptive_quantile must be in (0, 1]");
  require(adaptive_mult > 0, "adaptive_mult must be > 0");
  require(min_correspondences >= 3, "min_correspondences must be >= 3");
  require(max_correction_xy > 0 && max_correction_theta > 0, "max_correction_* must be > 0");
  require(range_sigma > 0, "range_sigma must be > 0");
}

void PlicpParams::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_iterations, "Iteration cap");
  MRPT_SAVE_CONFIG_VAR_COMMENT(epsilon_xy, "[m] stop when a step moves less than this...");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("epsilon_theta_DEG", epsilon_theta, "[deg] ...and turns less than this");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_correspondence_dist, "[m] farther point pairs are not matched, once converged");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_segment_length, "[m] shortest reference segment j1-j2 that defines a normal");
  MRPT_SAVE_CONFIG_VAR_COMMENT(remove_doubles, "Keep only the nearest of several points matched to one reference point");
  MRPT_SAVE_CONFIG_VAR_COMMENT(trim_keep_fraction, "Keep at most this fraction of the best matches");
  MRPT_SAVE_CONFIG_VAR_COMMENT(adaptive_quantile, "Adaptive trimming: this error quantile...");
  MRPT_SAVE_CONFIG_VAR_COMMENT(adaptive_mult, "...times this is the largest error kept");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_correspondences, "Fewer valid correspondences: the match fails");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_correction_xy, "[m] results farther from the guess are 'diverged'");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("max_correction_theta_DEG", max_correction_theta, "[deg] same for rotation");
  MRPT_SAVE_CONFIG_VAR_COMMENT(range_sigma, "[m] range noise std (sensor datasheet), for the covariance");
  MRPT_SAVE_CONFIG_VAR_COMMENT(covariance_from_residuals, "Scale the covariance by sum r^2 / (n - 3) / range_sigma^2 when above 1 (a posteriori variance factor)");
}

}  // namespace swslam::plicp

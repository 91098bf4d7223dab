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
  MRPT_LOAD_CONFIG_VAR_CS(initial_correspondence_dist, double);
  MRPT_LOAD_CONFIG_VAR_CS(coarse_start_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(retry_below_inlier_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(retry_rotations, int);
  retry_rotation_step = mrpt::DEG2RAD(
      c.read_double(s, "retry_rotation_step_DEG", mrpt::RAD2DEG(retry_rotation_step)));
  MRPT_LOAD_CONFIG_VAR_CS(retry_min_gain, double);
  point_spacing = mrpt::DEG2RAD(c.read_double(s, "point_spacing_DEG", mrpt::RAD2DEG(point_spacing)));
  MRPT_LOAD_CONFIG_VAR_CS(min_segment_length, double);
  MRPT_LOAD_CONFIG_VAR_CS(remove_doubles, bool);
  MRPT_LOAD_CONFIG_VAR_CS(early_doubles_ratio, double);
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
  require(initial_correspondence_dist >= max_correspondence_dist,
          "initial_correspondence_dist must be >= max_correspondence_dist");
  require(retry_below_inlier_fraction >= 0 && retry_below_inlier_fraction <= 1,
          "retry_below_inlier_fraction must be in [0, 1]");
  require(retry_rotations >= 0, "retry_rotations must be >= 0");
  require(retry_rotation_step > 0, "retry_rotation_step_DEG must be > 0");
  require(retry_min_gain >= 1, "retry_min_gain must be >= 1");
  require(coarse_start_fraction >= 0 && coarse_start_fraction <= 1, "coarse_start_fraction must be in [0, 1]");
  require(point_spacing >= 0 && point_spacing <= 2 * M_PI, "point_spacing_DEG must be in [0, 360]");
  require(min_segment_length >= 0, "min_segment_length must be >= 0");
  require(early_doubles_ratio == 0 || early_doubles_ratio >= 1, "early_doubles_ratio must be 0 or >= 1");
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
  MRPT_SAVE_CONFIG_VAR_COMMENT(initial_correspondence_dist, "[m] matching radius of the first iterations (halved as the estimate settles)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(retry_below_inlier_fraction, "Retry from rotated guesses when fewer points end within 3 range_sigma of the reference");
  MRPT_SAVE_CONFIG_VAR_COMMENT(retry_rotations, "Retries: the guess turned by +-1..k steps...");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("retry_rotation_step_DEG", retry_rotation_step, "[deg] ...of this");
  MRPT_SAVE_CONFIG_VAR_COMMENT(retry_min_gain, "A retry wins only with this many times the first run's inliers");
  MRPT_SAVE_CONFIG_VAR_COMMENT(coarse_start_fraction, "Start coarse if the guess matches fewer than this fraction of points within max_correspondence_dist");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("point_spacing_DEG", point_spacing, "[deg] iterate on every k-th current ray, k = round(this / beam spacing), then one step with all rays (0: all rays)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_segment_length, "[m] shortest reference segment j1-j2 that defines a normal");
  MRPT_SAVE_CONFIG_VAR_COMMENT(remove_doubles, "Keep only the nearest of several points matched to one reference point");
  MRPT_SAVE_CONFIG_VAR_COMMENT(early_doubles_ratio, "Until the estimate first settles, keep doubles within this many times the nearest's distance (0: one per reference point throughout)");
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

#include <swslam/correlative/params.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/core/bits_math.h>

#include <cmath>
#include <stdexcept>

namespace swslam::correlative
{
void CorrelativeParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
  MRPT_LOAD_CONFIG_VAR_CS(enabled, bool);
  MRPT_LOAD_CONFIG_VAR_CS(trigger_correction_xy, double);
  trigger_correction_theta = mrpt::DEG2RAD(
      c.read_double(s, "trigger_correction_theta_DEG", mrpt::RAD2DEG(trigger_correction_theta)));
  MRPT_LOAD_CONFIG_VAR_CS(trigger_inlier_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(trust_prediction_after, int);
  MRPT_LOAD_CONFIG_VAR_CS(submap_keyframes, int);
  MRPT_LOAD_CONFIG_VAR_CS(resolution, double);
  MRPT_LOAD_CONFIG_VAR_CS(sigma, double);
  MRPT_LOAD_CONFIG_VAR_CS(free_space_score, double);
  MRPT_LOAD_CONFIG_VAR_CS(window_xy, double);
  window_theta = mrpt::DEG2RAD(c.read_double(s, "window_theta_DEG", mrpt::RAD2DEG(window_theta)));
  theta_step = mrpt::DEG2RAD(c.read_double(s, "theta_step_DEG", mrpt::RAD2DEG(theta_step)));
  MRPT_LOAD_CONFIG_VAR_CS(cost_per_m, double);
  MRPT_LOAD_CONFIG_VAR_CS(cost_per_rad, double);
  MRPT_LOAD_CONFIG_VAR_CS(max_range, double);
  MRPT_LOAD_CONFIG_VAR_CS(min_score, double);
  MRPT_LOAD_CONFIG_VAR_CS(min_score_gain, double);
  MRPT_LOAD_CONFIG_VAR_CS(common_points_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(surface_goes_on_ratio, double);
  MRPT_LOAD_CONFIG_VAR_CS(refine_correspondence_dist, double);
  MRPT_LOAD_CONFIG_VAR_CS(prediction_decides_share, double);
  MRPT_LOAD_CONFIG_VAR_CS(steady_prior_cost, double);
  MRPT_LOAD_CONFIG_VAR_CS(steady_sigma_min, double);
  MRPT_LOAD_CONFIG_VAR_CS(steady_min_step, double);
  auto require = [&](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("config [") + s + "]: " + what);
  };
  require(trigger_correction_xy >= 0 && trigger_correction_theta >= 0,
          "trigger_correction_xy and trigger_correction_theta_DEG must be >= 0");
  require(trigger_inlier_fraction >= 0 && trigger_inlier_fraction <= 1,
          "trigger_inlier_fraction must be in [0, 1]");
  require(trust_prediction_after >= 0, "trust_prediction_after must be >= 0");
  require(submap_keyframes >= 1, "submap_keyframes must be >= 1");
  require(resolution > 0 && resolution <= 10 && sigma > 0, "resolution must be in (0, 10] m, sigma > 0");
  // Each point's kernel covers (2 ceil(3 sigma / resolution) + 1)^2 cells of the score grid.
  require(sigma <= 10 * resolution, "sigma must be at most 10 resolution");
  require(free_space_score >= -1 && free_space_score <= 0, "free_space_score must be in [-1, 0]");
  // Bounds that keep the pyramid (padded by the window) and the rotated lattices in memory.
  require(window_xy >= 0 && window_xy <= 256 * resolution,
          "window_xy must be in [0, 256 resolution]");
  require(window_theta >= 0 && window_theta <= 2 * M_PI, "window_theta_DEG must be in [0, 360]");
  require(theta_step >= mrpt::DEG2RAD(0.1) && theta_step <= 2 * M_PI, "theta_step_DEG must be in [0.1, 360]");
  require(cost_per_m >= 0 && cost_per_rad >= 0, "cost_per_m and cost_per_rad must be >= 0");
  require(max_range > 0, "max_range must be > 0");
  require(min_score >= 0 && min_score <= 1, "min_score must be in [0, 1]");
  require(min_score_gain >= 0, "min_score_gain must be >= 0");
  require(common_points_fraction >= 0 && common_points_fraction <= 1, "common_points_fraction must be in [0, 1]");
  require(surface_goes_on_ratio >= 0, "surface_goes_on_ratio must be >= 0");
  require(refine_correspondence_dist >= 0, "refine_correspondence_dist must be >= 0");
  require(prediction_decides_share >= 0 && prediction_decides_share <= 1, "prediction_decides_share must be in [0, 1]");
  require(steady_prior_cost >= 0, "steady_prior_cost must be >= 0");
  require(steady_sigma_min > 0, "steady_sigma_min must be > 0");
  require(steady_min_step >= 0, "steady_min_step must be >= 0");
}

void CorrelativeParams::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
  MRPT_SAVE_CONFIG_VAR_COMMENT(enabled, "search when tracking's prediction or a loop check's match failed");
  MRPT_SAVE_CONFIG_VAR_COMMENT(trigger_correction_xy, "[m] search if the match moved the prediction more than this...");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("trigger_correction_theta_DEG", trigger_correction_theta, "[deg] ...or turned it more than this...");
  MRPT_SAVE_CONFIG_VAR_COMMENT(trigger_inlier_fraction, "...or ended with fewer inliers than this fraction");
  MRPT_SAVE_CONFIG_VAR_COMMENT(trust_prediction_after, "...unless it kept a prediction confirmed this many scans in a row (0: never)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(submap_keyframes, "the score grid holds the last this many keyframes' points");
  MRPT_SAVE_CONFIG_VAR_COMMENT(resolution, "[m] score grid cell and translation step");
  MRPT_SAVE_CONFIG_VAR_COMMENT(sigma, "[m] score kernel sigma");
  MRPT_SAVE_CONFIG_VAR_COMMENT(free_space_score, "score of a point where the keyframes saw free space, in [-1, 0]");
  MRPT_SAVE_CONFIG_VAR_COMMENT(window_xy, "[m] translations searched around the prediction");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("window_theta_DEG", window_theta, "[deg] rotations searched");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("theta_step_DEG", theta_step, "[deg] rotation step");
  MRPT_SAVE_CONFIG_VAR_COMMENT(cost_per_m, "motion prior: score lost per metre from the prediction");
  MRPT_SAVE_CONFIG_VAR_COMMENT(cost_per_rad, "...and per radian");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_range, "[m] farther points are not used");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_score, "least score of a search result");
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_score_gain, "the searched match wins only with this much higher objective");
  MRPT_SAVE_CONFIG_VAR_COMMENT(common_points_fraction, "compare the two matches on the points that can tell them apart, when at least this fraction can (0: on all)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(surface_goes_on_ratio, "a point unseen at one pose tells nothing when at the other it lies on a surface going on (the cell beyond scores this fraction of its own)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(refine_correspondence_dist, "[m] PLICP radius of the second refinement when the first scored below the search's pose (0: none)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(prediction_decides_share, "the prediction chooses between the two matches where the searched one has under this share of its strongest information along their difference (0: never)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(steady_prior_cost, "steady-motion prior: score lost at one sigma from the prediction (0: none)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(steady_sigma_min, "[m] least sigma: the spread of the recent steps");
  MRPT_SAVE_CONFIG_VAR_COMMENT(steady_min_step, "[m] the prior applies while the last 3 steps average at least this");
}

}  // namespace swslam::correlative

#include <swslam/tracking/params.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/core/bits_math.h>

#include <cmath>
#include <stdexcept>

namespace swslam::tracking
{
void TrackingParams::loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s)
{
  MRPT_LOAD_CONFIG_VAR_CS(min_range, double);
  MRPT_LOAD_CONFIG_VAR_CS(keyframe_translation, double);
  keyframe_rotation =
      mrpt::DEG2RAD(c.read_double(s, "keyframe_rotation_DEG", mrpt::RAD2DEG(keyframe_rotation)));
  MRPT_LOAD_CONFIG_VAR_CS(dense_radius, double);
  MRPT_LOAD_CONFIG_VAR_CS(max_dense_edges, int);
  MRPT_LOAD_CONFIG_VAR_CS(dense_max_index_gap, int);
  MRPT_LOAD_CONFIG_VAR_CS(dense_gate_xy, double);
  dense_gate_theta =
      mrpt::DEG2RAD(c.read_double(s, "dense_gate_theta_DEG", mrpt::RAD2DEG(dense_gate_theta)));
  MRPT_LOAD_CONFIG_VAR_CS(lost_prior_sigma_xy, double);
  lost_prior_sigma_theta = mrpt::DEG2RAD(
      c.read_double(s, "lost_prior_sigma_theta_DEG", mrpt::RAD2DEG(lost_prior_sigma_theta)));
  MRPT_LOAD_CONFIG_VAR_CS(constant_velocity, bool);
  MRPT_LOAD_CONFIG_VAR_CS(max_interval_ratio, double);
  MRPT_LOAD_CONFIG_VAR_CS(ambiguity_factor, double);
  MRPT_LOAD_CONFIG_VAR_CS(unobservable_min_rays, int);
  MRPT_LOAD_CONFIG_VAR_CS(searched_min_inlier_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(overlap_search_min_inlier_fraction, double);
  MRPT_LOAD_CONFIG_VAR_CS(unmatched_scans_skipped, int);
  MRPT_LOAD_CONFIG_VAR_CS(search_first_match, bool);
  auto require = [&](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("config [") + s + "]: " + what);
  };
  require(min_range >= 0, "min_range must be >= 0");
  require(keyframe_translation > 0 && keyframe_rotation > 0,
          "keyframe_translation and keyframe_rotation_DEG must be > 0");
  require(dense_radius >= 0, "dense_radius must be >= 0");
  require(max_dense_edges >= 0, "max_dense_edges must be >= 0");
  require(dense_max_index_gap >= 1, "dense_max_index_gap must be >= 1");
  require(dense_gate_xy > 0 && dense_gate_theta > 0, "dense_gate_xy and dense_gate_theta_DEG must be > 0");
  require(lost_prior_sigma_xy > 0 && lost_prior_sigma_theta > 0, "lost_prior_sigma_* must be > 0");
  require(max_interval_ratio >= 1, "max_interval_ratio must be >= 1");
  require(ambiguity_factor >= 0 && std::isfinite(ambiguity_factor), "ambiguity_factor must be >= 0");
  require(unobservable_min_rays >= 0, "unobservable_min_rays must be >= 0");
  require(searched_min_inlier_fraction >= 0 && searched_min_inlier_fraction <= 1,
          "searched_min_inlier_fraction must be in [0, 1]");
  require(overlap_search_min_inlier_fraction >= 0 && overlap_search_min_inlier_fraction <= 1,
          "overlap_search_min_inlier_fraction must be in [0, 1]");
  require(unmatched_scans_skipped >= 0, "unmatched_scans_skipped must be >= 0");
}

void TrackingParams::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
  MRPT_SAVE_CONFIG_VAR_COMMENT(min_range, "[m] shorter readings are dropped");
  MRPT_SAVE_CONFIG_VAR_COMMENT(keyframe_translation, "[m] a new node past this motion from the last...");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("keyframe_rotation_DEG", keyframe_rotation, "[deg] ...or this turn");
  MRPT_SAVE_CONFIG_VAR_COMMENT(dense_radius, "[m] a new node is matched with every node this close");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_dense_edges, "at most this many dense edges per node, nearest first");
  MRPT_SAVE_CONFIG_VAR_COMMENT(dense_max_index_gap, "dense edges only to the last this many nodes (older ones: loop candidates)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(dense_gate_xy, "[m] a dense match farther than this from the tracked estimate is dropped...");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("dense_gate_theta_DEG", dense_gate_theta, "[deg] ...or turned more than this");
  MRPT_SAVE_CONFIG_VAR_COMMENT(lost_prior_sigma_xy, "[m] std of the weak prior edge of a node made without a match");
  MRPT_SAVE_CONFIG_VAR_DEGREES_COMMENT("lost_prior_sigma_theta_DEG", lost_prior_sigma_theta, "[deg] same for rotation");
  MRPT_SAVE_CONFIG_VAR_COMMENT(constant_velocity, "predict the previous motion over the new scan interval (false: per scan)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(max_interval_ratio, "...scaled by at most this (or 1 / this) times");
  MRPT_SAVE_CONFIG_VAR_COMMENT(ambiguity_factor, "a match direction with less information than this many times what noise fakes is weak (0: never)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(unobservable_min_rays, "a match direction fewer rays of either scan face is unobservable: the prediction decides (0: never)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(searched_min_inlier_fraction, "a match chosen after the search counts only with this fraction of the valid rays as inliers (0: any)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(overlap_search_min_inlier_fraction, "a match the search found replaces one that stayed on its prediction (searched for its little overlap) only with this fraction of the valid rays as inliers");
  MRPT_SAVE_CONFIG_VAR_COMMENT(search_first_match, "the first match of a run without odometry is found by the search before any PLICP match (its prediction is a guess)");
  MRPT_SAVE_CONFIG_VAR_COMMENT(unmatched_scans_skipped, "an unmatched scan past the keyframe threshold is no node while at most this many in a row were unmatched (0: always a node)");
}

}  // namespace swslam::tracking

#include <swslam/tracking/params.h>

namespace swslam::tracking
{
const common::ParamTable<TrackingParams>& TrackingParams::table()
{
  using P = TrackingParams;
  using common::Tier;
  static const auto t =
      common::ParamTable<P>("tracking", "Local tracking (paper sec. II.C): each scan matched against the last keyframe.")
          .real("min_range", &P::min_range, "m", common::atLeast(0), "shorter readings are dropped (the sensor's blind zone)",
                Tier::User)
          .real("keyframe_translation", &P::keyframe_translation, "m", common::above(0),
                "a new graph node past this motion from the last one...", Tier::User)
          .angle("keyframe_rotation_DEG", &P::keyframe_rotation, common::above(0), "...or this turn", Tier::User)
          .real("dense_radius", &P::dense_radius, "m", common::atLeast(0),
                "a new node is matched with every recent node this close (dense graph, Fig. 2)", Tier::User)
          .integer("max_dense_edges", &P::max_dense_edges, "", common::atLeast(0), "dense edges per node at most, nearest first")
          .integer("dense_max_index_gap", &P::dense_max_index_gap, "", common::atLeast(1),
                   "dense edges only to the last this many nodes (older ones are loop candidates)")
          .real("dense_gate_xy", &P::dense_gate_xy, "m", common::above(0),
                "a dense match farther than this from the tracked estimate is dropped...")
          .angle("dense_gate_theta_DEG", &P::dense_gate_theta, common::above(0), "...or turned more than this")
          .real("lost_prior_sigma_xy", &P::lost_prior_sigma_xy, "m", common::above(0),
                "std of the weak prior edge of a node made while matching failed (open water)")
          .angle("lost_prior_sigma_theta_DEG", &P::lost_prior_sigma_theta, common::above(0), "same for rotation")
          .flag("constant_velocity", &P::constant_velocity,
                "predict the previous motion at constant velocity over the scan's interval (false: per scan, as the paper)")
          .real("constant_velocity_horizon", &P::constant_velocity_horizon, "s", common::above(0),
                "...exactly while both intervals are within this long (a vehicle's speed holds)...")
          .real("max_interval_ratio", &P::max_interval_ratio, "", common::atLeast(1),
                "...else scaled by at most this many times (or 1 / this), or over at most the horizon")
          .real("ambiguity_factor", &P::ambiguity_factor, "", common::atLeast(0),
                "a match direction with less information than this many times what noise fakes is weak (0: never)")
          .integer("unobservable_min_rays", &P::unobservable_min_rays, "", common::atLeast(0),
                   "a weak direction fewer rays of either scan face is unobservable: the prediction decides it (0: never)")
          .real("searched_min_inlier_fraction", &P::searched_min_inlier_fraction, "", common::between(0, 1),
                "a match chosen after the search counts only with this fraction of the valid rays as inliers")
          .real("overlap_search_min_inlier_fraction", &P::overlap_search_min_inlier_fraction, "", common::between(0, 1),
                "a searched match replaces one searched for its little overlap only with this fraction as inliers")
          .integer("unmatched_scans_skipped", &P::unmatched_scans_skipped, "", common::atLeast(0),
                   "an unmatched scan is no node while at most this many in a row were unmatched (0: always a node)")
          .flag("search_first_match", &P::search_first_match,
                "the first match of a run without odometry is found by the search before any PLICP match")
          .real("trigger_correction_xy", &P::trigger_correction_xy, "m", common::atLeast(0),
                "search if the first match moved the prediction more than this...")
          .angle("trigger_correction_theta_DEG", &P::trigger_correction_theta, common::atLeast(0),
                 "...or turned it more than this...")
          .real("trigger_inlier_fraction", &P::trigger_inlier_fraction, "", common::between(0, 1),
                "...or kept fewer than this fraction of the points within 3 range_sigma of the keyframe")
          .integer("trust_prediction_after", &P::trust_prediction_after, "", common::atLeast(0),
                   "...unless it stayed on a prediction the last this many scans confirmed (0: always search)")
          .integer("submap_keyframes", &P::submap_keyframes, "", common::atLeast(1),
                   "the search's score grid holds the points of the last this many keyframes")
          .real("min_score_gain", &P::min_score_gain, "", common::atLeast(0),
                "the searched match replaces the first only with an objective this much higher")
          .real("common_points_fraction", &P::common_points_fraction, "", common::between(0, 1),
                "compare the two matches on the points that can tell them apart when this fraction can (0: on all)")
          .real("surface_goes_on_ratio", &P::surface_goes_on_ratio, "", common::atLeast(0),
                "a point unseen at one pose tells nothing if at the other it lies on a surface going on past it")
          .real("refine_correspondence_dist", &P::refine_correspondence_dist, "m", common::atLeast(0),
                "PLICP radius of a second refinement when the first left the search's basin (0: none)")
          .real("prediction_decides_share", &P::prediction_decides_share, "", common::between(0, 1),
                "the prediction chooses between two matches where the searched one has under this share of information (0: never)")
          .real("steady_prior_cost", &P::steady_prior_cost, "", common::atLeast(0),
                "steady-motion prior: the search's score lost at one sigma from the prediction (0: none)")
          .real("steady_sigma_min", &P::steady_sigma_min, "m", common::above(0), "least sigma of the steady-motion prior")
          .real("steady_min_step", &P::steady_min_step, "m", common::atLeast(0),
                "the steady-motion prior applies while the last 3 steps average at least this")
          .real("placement_acceleration", &P::placement_acceleration, "m/s^2", common::above(0),
                "scans between keyframes: the acceleration that takes them off constant motion between the two...")
          .angle("placement_angular_acceleration_DEG", &P::placement_angular_acceleration, common::above(0),
                 "...and the angular one, per s^2 (where its points inform, their match decides)");
  return t;
}

}  // namespace swslam::tracking

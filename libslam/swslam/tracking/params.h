#pragma once
// Parameters of local tracking (paper sec. II.C), section [tracking].

#include <swslam/common/param_table.h>

#include <mrpt/core/bits_math.h>

namespace swslam::tracking
{
/** Parameters of local tracking, section [tracking]: declared in table() (params.cpp). */
struct TrackingParams
{
  double min_range = 0.1;              ///< [m] shorter readings are dropped (sensor's blind zone)
  double keyframe_translation = 0.5;   ///< [m] a new node past this motion from the last one...
  double keyframe_rotation = mrpt::DEG2RAD(10.0);  ///< [rad] ...or this turn
  double dense_radius = 4.0;           ///< [m] a new node is matched with every node this close (Fig. 2)
  int max_dense_edges = 8;             ///< at most this many dense edges per node, nearest first
  int dense_max_index_gap = 30;        ///< dense edges only to the last this many nodes (older: loops)
  double dense_gate_xy = 0.3;          ///< [m] a dense match farther than this from the tracked estimate is dropped...
  double dense_gate_theta = mrpt::DEG2RAD(5.0);  ///< [rad] ...or turned more
  double lost_prior_sigma_xy = 1.0;    ///< [m] std of the weak prior edge when a node is made without a match
  double lost_prior_sigma_theta = mrpt::DEG2RAD(10.0);  ///< [rad]
  bool constant_velocity = true;   ///< predict the previous motion over the new scan interval (false: per scan)
  double constant_velocity_horizon = 1.0;  ///< [s] ...exactly while both intervals are within this...
  double max_interval_ratio = 4.0;  ///< ...else scaled by at most this (or 1 / this) times
  /** A match direction is weak (ambiguous) when its information is below this many times what
   * noise fakes along a featureless one (0: never; tracking/ambiguity.h) */
  double ambiguity_factor = 1.0;
  /** A direction of a match that fewer than this many rays of the keyframe or of the scan
   * face (a single wall's line) is unobservable: the prediction decides along it, with the
   * variance of its recent errors (0: never; tracking/ambiguity.h) */
  int unobservable_min_rays = 3;
  /** A match chosen after the correlative search (the prediction failed) counts only if at
   * least this fraction of the scan's valid rays are its inliers; else the scan is unmatched
   * and the prediction carries it (0: any match counts). */
  double searched_min_inlier_fraction = 0.1;
  /** When the first match stayed on its prediction and was searched only for its little
   * overlap (an object in front of the sensor, a door), a match the search found elsewhere
   * replaces it only with at least this fraction of the valid rays as inliers; else the first
   * match stays. */
  double overlap_search_min_inlier_fraction = 0.2;
  /** An unmatched scan past the keyframe threshold becomes no node while at most this many
   * scans in a row were unmatched: the next scan is matched against the last keyframe again,
   * and an odd scan (someone in front of the sensor) never joins the graph (0: always a node). */
  int unmatched_scans_skipped = 2;
  /** The first match of a run without odometry (its prediction, no motion, is a guess) is
   * found by the correlative search before any PLICP match, PLICP running from the search's
   * best pose (from the guess only if the search finds nothing). */
  bool search_first_match = true;

  // When a scan is searched: its first match against the keyframe...
  double trigger_correction_xy = 0.1;  ///< [m] ...moved the prediction more than this,
  double trigger_correction_theta = mrpt::DEG2RAD(2.0);  ///< [rad] or turned it more,
  double trigger_inlier_fraction = 0.5;  ///< or kept fewer inliers than this fraction (or failed)...
  int trust_prediction_after = 10;  ///< ...unless it stayed on a prediction this many scans confirmed (0: never)
  int submap_keyframes = 5;  ///< the search's score grid holds the points of the last this many keyframes
  // Which of the first and the searched match is kept.
  double min_score_gain = 0.02;  ///< the searched match replaces the first only with an objective this much higher
  /** the two matches are compared on the points that can tell them apart (correlative::
   * commonScores), when at least this fraction of the points can; else on all the points
   * (0: always on all) */
  double common_points_fraction = 0.5;
  /** a point in unseen space at one pose tells nothing against the other pose when there it
   * lies on a surface that goes on: the cell as far beyond scores at least this fraction of
   * its own */
  double surface_goes_on_ratio = 0.25;
  /** [m] when PLICP from the search's pose ends at a lower objective than that pose's, it is
   * run again from it with this correspondence radius (0: never), the better one kept */
  double refine_correspondence_dist = 0.3;
  /** where the first and the searched match differ along a direction in which the searched
   * one has under this share of its strongest information (informationShare), the scans cannot
   * tell them apart: the one nearer the prediction along their difference is kept
   * (predictionChoice; 0: never) */
  double prediction_decides_share = 0.001;
  // Steady-motion prior (steady_motion.h): while the last 3 steps average at least
  // steady_min_step, the search also loses steady_prior_cost (d / sigma)^2 at a distance d from
  // the prediction, sigma the spread of the recent steps (at least steady_sigma_min).
  double steady_prior_cost = 0.002;  ///< score lost at one sigma (0: no such prior)
  double steady_sigma_min = 0.3;     ///< [m]
  double steady_min_step = 0.5;      ///< [m] per scan
  // Scans between keyframes in the trajectory (placement.h): how far the vehicle's motion
  // strays from constant velocity between two keyframes.
  double placement_acceleration = 1.0;                         ///< [m/s^2]
  double placement_angular_acceleration = mrpt::DEG2RAD(60.0);  ///< [rad/s^2]

  static const common::ParamTable<TrackingParams>& table();
};

}  // namespace swslam::tracking

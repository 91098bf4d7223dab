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
  double max_interval_ratio = 4.0;  ///< ...scaled by at most this (or 1 / this) times
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

  static const common::ParamTable<TrackingParams>& table();
};

}  // namespace swslam::tracking

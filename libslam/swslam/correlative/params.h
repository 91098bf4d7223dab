#pragma once
// Parameters of the correlative search that re-aligns a tracking match whose prediction
// failed, section [correlative] (doc/tracking.md).

#include <swslam/common/param_table.h>

#include <mrpt/core/bits_math.h>

namespace swslam::correlative
{
/** Section [correlative]: declared in table() (params.cpp). */
struct CorrelativeParams
{
  bool enabled = true;  ///< false: neither tracking nor loop checks ever search
  // When a scan is searched: its match against the keyframe ...
  double trigger_correction_xy = 0.1;  ///< [m] ... moved the prediction more than this,
  double trigger_correction_theta = mrpt::DEG2RAD(2.0);  ///< [rad] or turned it more,
  double trigger_inlier_fraction = 0.5;  ///< or ended with fewer inliers than this (or failed)
  int trust_prediction_after = 10;  ///< ...unless it kept a prediction confirmed this many scans in a row (0: never)
  // The search.
  int submap_keyframes = 5;  ///< the score grid holds the points of the last this many keyframes
  double resolution = 0.1;  ///< [m] score grid cell, and translation step
  double sigma = 0.1;       ///< [m] score kernel: exp(-d^2 / 2 sigma^2)
  double free_space_score = -1.0;  ///< in [-1, 0]: score of a point where the keyframes saw free space
  double window_xy = 3.0;   ///< [m] translations within +- this of the prediction
  double window_theta = mrpt::DEG2RAD(180.0);  ///< [rad] rotations within +- this
  double theta_step = mrpt::DEG2RAD(1.0);  ///< [rad] rotation step
  double cost_per_m = 0.02;    ///< motion prior: objective = score - cost_per_m |t - t_pred| ...
  double cost_per_rad = 0.1;  ///< ... - cost_per_rad |theta - theta_pred|
  double max_range = 30.0;  ///< [m] farther points are left out of the grid and the search
  double min_score = 0.1;   ///< a search result scores at least this (mean cell value, 0..1)
  double min_score_gain = 0.02;  ///< the searched match replaces the first only if its objective is this much higher
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
  // Steady-motion prior (tracking/steady_motion.h): while the last 3 steps average at least
  // steady_min_step, the search also loses steady_prior_cost (d / sigma)^2 at a distance d from
  // the prediction, sigma the spread of the recent steps (at least steady_sigma_min).
  double steady_prior_cost = 0.002;  ///< score lost at one sigma (0: no such prior)
  double steady_sigma_min = 0.3;     ///< [m]
  double steady_min_step = 0.5;      ///< [m] per scan

  static const common::ParamTable<CorrelativeParams>& table();
};

}  // namespace swslam::correlative

#pragma once
// Parameters of localization on a saved map (doc/localization.md), section [localization].

#include <swslam/common/param_table.h>

#include <mrpt/core/bits_math.h>

namespace swslam::localize
{
/** Section [localization]: declared in table() (params.cpp). */
struct LocalizationParams
{
  /** A relocalization: the whole-map search's best pose scores at least this (mean score of
   * the scan's points on the map, 0..1; where the map saw free space a point scores < 0). */
  double min_score = 0.5;
  /** ...and the best pose elsewhere (farther than ambiguity_radius) scores at most this
   * fraction of it, or the place is ambiguous and the next scans are tried. */
  double max_second_ratio = 0.85;
  double ambiguity_radius = 2.0;  ///< [m]
  double theta_step = mrpt::DEG2RAD(0.5);  ///< [rad] rotation step of the whole-map search
  /** A match explains at least this fraction of the scan's valid rays (PLICP inliers), or
   * the scan is placed by the prediction and counts towards lost. */
  double min_inlier_fraction = 0.5;
  double lost_after = 1.0;            ///< [s] placed by the prediction this long: lost
  double relocalize_interval = 0.25;  ///< [s] of log between two whole-map searches while lost

  static const common::ParamTable<LocalizationParams>& table();
};

}  // namespace swslam::localize

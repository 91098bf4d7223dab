#pragma once
// The matcher's parameters, section [plicp].

#include <swslam/common/param_table.h>

#include <mrpt/core/bits_math.h>

namespace swslam::plicp
{
/** Parameters of the matcher, section [plicp]: declared in table() (params.cpp). */
struct PlicpParams
{
  int max_iterations = 40;           ///< iteration cap
  double epsilon_xy = 5e-4;          ///< [m] stop when the step's translation is below
  double epsilon_theta = mrpt::DEG2RAD(0.0057);  ///< [rad] and its rotation below
  double max_correspondence_dist = 1.0;  ///< [m] farther point pairs are not matched
  double min_segment_length = 0.2;   ///< [m] shortest j1-j2 segment defining a normal
  bool remove_doubles = true;        ///< keep one match per reference point
  double trim_keep_fraction = 0.95;  ///< keep at most this fraction of the best matches
  double adaptive_quantile = 0.7;    ///< adaptive trimming: error quantile ...
  double adaptive_mult = 3.0;        ///< ... times this is the largest error kept
  int min_correspondences = 20;      ///< fewer valid correspondences: the match fails
  double max_correction_xy = 5.0;    ///< [m] a result farther from the guess is "diverged"
  double max_correction_theta = mrpt::DEG2RAD(90.0);  ///< [rad] same for rotation
  double range_sigma = 0.03;         ///< [m] range noise std for the covariance (datasheet)
  /** scale the covariance by the a posteriori variance factor, when the residuals show more
   * noise than range_sigma (plicp::residualVarianceFactor) */
  bool covariance_from_residuals = true;

  static const common::ParamTable<PlicpParams>& table();
};

}  // namespace swslam::plicp

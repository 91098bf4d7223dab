#pragma once
// The matcher's parameters, section [plicp].

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/core/bits_math.h>

#include <cmath>
#include <string>

namespace swslam::plicp
{
/** Parameters of the matcher, section [plicp]. */
struct PlicpParams : public mrpt::config::CLoadableOptions
{
  int max_iterations = 40;           ///< iteration cap (per run from one start)
  double epsilon_xy = 5e-4;          ///< [m] stop when the step's translation is below
  double epsilon_theta = 1e-4;       ///< [rad] (ini: epsilon_theta_DEG) and its rotation below
  double max_correspondence_dist = 1.0;  ///< [m] farther point pairs are not matched ...
  double initial_correspondence_dist = 4.0;  ///< [m] ... after a coarse-to-fine start from this
  double coarse_start_fraction = 0.0;  ///< start coarse if the guess matches fewer points than this (0: never)
  double retry_below_inlier_fraction = 0.0;  ///< retry from rotated guesses below this inlier fraction (0: never)
  int retry_rotations = 3;                ///< retries: the guess turned by +-1..k steps...
  double retry_rotation_step = 20.0 * M_PI / 180;  ///< [rad] ...of this (ini: retry_rotation_step_DEG)
  double retry_min_gain = 3.0;            ///< a retry wins only with this many times the inliers
  double point_spacing = 0.0;  ///< [rad] iterate on current rays about this far apart, then one full step (ini: point_spacing_DEG; 0: every ray)
  double min_segment_length = 0.2;   ///< [m] shortest j1-j2 segment defining a normal
  bool remove_doubles = true;        ///< keep one match per reference point (at the final radius)
  /** until the estimate first settles, keep a double whose distance to its reference point is
   * at most this many times the nearest one's (csm's rule), then one per reference point
   * (0: one per reference point from the first iteration) */
  double early_doubles_ratio = 0.0;
  double trim_keep_fraction = 0.95;  ///< keep at most this fraction of the best matches
  double adaptive_quantile = 0.7;    ///< adaptive trimming: error quantile ...
  double adaptive_mult = 3.0;        ///< ... times this is the largest error kept
  int min_correspondences = 20;      ///< fewer valid correspondences: the match fails
  double max_correction_xy = 5.0;    ///< [m] a result farther from the guess is "diverged"
  double max_correction_theta = M_PI / 2;  ///< [rad] (ini: max_correction_theta_DEG)
  double range_sigma = 0.03;         ///< [m] range noise std for the covariance (datasheet)
  /** scale the covariance by the a posteriori variance factor, when the residuals show more
   * noise than range_sigma (plicp::residualVarianceFactor) */
  bool covariance_from_residuals = true;

  void loadFromConfigFile(const mrpt::config::CConfigFileBase& c, const std::string& s) override;
  void saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const override;
};

}  // namespace swslam::plicp

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
  double max_correspondence_dist = 1.0;  ///< [m] farther point pairs are not matched
  double min_segment_length = 0.2;   ///< [m] shortest j1-j2 segment defining a normal
  bool remove_doubles = true;        ///< keep one match per reference point
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

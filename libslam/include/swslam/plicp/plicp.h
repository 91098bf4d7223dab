#pragma once
// PLICP scan matcher (paper sec. II.A-B): point-to-line ICP with the closed-form step of
// eq. (1)-(3) and the closed-form covariance of eq. (4)-(10).

#include <swslam/plicp/correspondences.h>
#include <swslam/scan.h>

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>
#include <string>

namespace swslam
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

enum class MatchStatus
{
  Converged,              ///< the step or the correspondence set stopped changing
  MaxIterations,          ///< iteration cap reached (result usable, less trusted)
  TooFewCorrespondences,  ///< fewer valid correspondences (or rays) than the minimum
  Diverged,               ///< the solve failed or the result left the plausible region
  InvalidInput,           ///< scans that cannot be matched (e.g. from different sensors)
};
const char* toString(MatchStatus s);

struct MatchResult
{
  MatchStatus status = MatchStatus::InvalidInput;
  mrpt::poses::CPose2D pose;  ///< current sensor pose in the reference sensor frame
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  ///< of [x, y, phi]
  int iterations = 0;
  size_t ref_valid_rays = 0, cur_valid_rays = 0;
  size_t correspondences = 0;   ///< valid correspondences at the end
  size_t inliers = 0;  ///< of them, those within 3 range_sigma of the reference surface
  double sum_sq_residuals = 0;  ///< sum of squared point-to-line distances at the end [m^2]
  double variance_factor = 1;   ///< the covariance's a posteriori scale (>= 1; 1 when not used)
  std::string message;          ///< why it failed, when it did

  bool ok() const { return status == MatchStatus::Converged || status == MatchStatus::MaxIterations; }
};

/** A reference scan with its precomputed search tables (reuse it for many matches). The
 * tables depend on params.min_segment_length, which matchScans() checks. */
struct ReferenceScan
{
  Scan scan;
  plicp::ReferenceIndex index;
  explicit ReferenceScan(Scan s, const PlicpParams& params = PlicpParams())
      : scan(std::move(s)), index(scan, params.min_segment_length)
  {
  }
};

/** Matches `cur` against `ref` starting from `initial_guess` (the current sensor pose in the
 * reference sensor frame). Never throws for bad data: the status says what went wrong. */
MatchResult matchScans(const ReferenceScan& ref, const Scan& cur,
                       const mrpt::poses::CPose2D& initial_guess, const PlicpParams& params);

}  // namespace swslam

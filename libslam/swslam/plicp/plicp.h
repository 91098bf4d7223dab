#pragma once
// PLICP scan matcher (paper sec. II.A-B): point-to-line ICP with the closed-form step of
// eq. (1)-(3) and the closed-form covariance of eq. (4)-(10).

#include <swslam/plicp/correspondences.h>
#include <swslam/plicp/params.h>
#include <swslam/sensor/scan.h>

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>
#include <string>

namespace swslam::plicp
{
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
  sensor::Scan scan;
  ReferenceIndex index;
  explicit ReferenceScan(sensor::Scan s, const PlicpParams& params = PlicpParams())
      : scan(std::move(s)), index(scan, params.min_segment_length)
  {
  }
};

/** Matches `cur` against `ref` starting from `initial_guess` (the current sensor pose in the
 * reference sensor frame). Never throws for bad data: the status says what went wrong. */
MatchResult matchScans(const ReferenceScan& ref, const sensor::Scan& cur,
                       const mrpt::poses::CPose2D& initial_guess, const PlicpParams& params);

}  // namespace swslam::plicp

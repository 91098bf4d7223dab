#pragma once
// The iterations of PLICP (paper sec. II.A): correspondences, outlier rejection, closed-form
// step, convergence; the coarse start and the rotated retries for poor guesses.

#include <swslam/plicp/plicp.h>

#include <Eigen/Core>
#include <string>
#include <vector>

namespace swslam::plicp
{
/** The state of one run of PLICP iterations. */
struct IcpRun
{
  Eigen::Vector3d x;  ///< [x, y, phi]: current sensor pose in the reference sensor frame
  std::vector<Correspondence> kept;  ///< the last correspondence set
  int iterations = 0;
  MatchStatus status = MatchStatus::MaxIterations;
  std::string message;  ///< why it failed, when it did
};

/** The current scan's points moved by x = [x, y, phi]. */
std::vector<Eigen::Vector2d> transformed(const sensor::Scan& s, const Eigen::Vector3d& x);
/** The same into `out` (resized; reuses its storage). */
void transformInto(const sensor::Scan& s, const Eigen::Vector3d& x, std::vector<Eigen::Vector2d>& out);

/** Point-to-line distance of each correspondence (eq. 1's residual). */
std::vector<double> lineErrors(const sensor::Scan& ref, const std::vector<Eigen::Vector2d>& cur_in_ref,
                               const std::vector<Correspondence>& cs);
/** The same with the normals from the reference's index tables (same values, faster). */
std::vector<double> lineErrors(const ReferenceScan& reference,
                               const std::vector<Eigen::Vector2d>& cur_in_ref,
                               const std::vector<Correspondence>& cs);
/** The same into `out` (resized; reuses its storage). */
void lineErrorsInto(const ReferenceScan& reference, const std::vector<Eigen::Vector2d>& cur_in_ref,
                    const std::vector<Correspondence>& cs, std::vector<double>& out);

/** PLICP from the guess x0 (coarse start if the guess is poor); if it ends with few inliers,
 * also from the guess turned by +-1..retry_rotations steps, keeping a retry only if it has
 * retry_min_gain times the inliers of the first run. Iterations are summed over runs. */
IcpRun runWithRetries(const ReferenceScan& reference, const sensor::Scan& cur, const Eigen::Vector3d& x0,
                      const PlicpParams& params);

/** One more iteration with every ray of `cur` (the run having converged on a decimated
 * copy): correspondences at max_correspondence_dist, outlier rejection, closed-form step.
 * On success run.x and run.kept (then indices into `cur`) are updated and it returns true;
 * with too few correspondences or a failed solve it returns false and leaves `run` as is. */
bool fullResolutionStep(const ReferenceScan& reference, const sensor::Scan& cur,
                        const PlicpParams& params, IcpRun& run);

}  // namespace swslam::plicp

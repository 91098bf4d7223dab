#pragma once
// The iterations of PLICP (paper sec. II.A): correspondences, outlier rejection, closed-form
// step, convergence.

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

/** PLICP iterations from the guess x0 until the correspondence set or the step settles
 * (Converged) or max_iterations; fails with TooFewCorrespondences or Diverged (run.message
 * says why). */
IcpRun iterate(const ReferenceScan& reference, const sensor::Scan& cur, const Eigen::Vector3d& x0,
               const PlicpParams& params);

}  // namespace swslam::plicp

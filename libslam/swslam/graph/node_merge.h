#pragma once
// Carrying an edge to the node another one was merged into (a reduced pose graph, Johannsson
// et al., ICRA 2013; doc/graph-optimization.md): a merged node is held at a measured pose
// relative to its anchor, so an edge naming it says as much of the anchor, with the
// attachment's uncertainty composed into its own. Measurements are as the graph keeps them:
// the mean is the pose of `to` seen from `from`, the information weighs the error of
// se2_error.h (in the measurement's own frame).

#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/poses/CPosePDFGaussianInf.h>

#include <Eigen/Core>

#include <optional>

namespace swslam::graph
{
/** A measurement (`mean`, `information` as above) as MRPT's Gaussian, whose covariance is in
 * the frame of the edge's first pose: the translation's turned by the measurement's heading.
 * What MRPT's composition and inversion take. */
mrpt::poses::CPosePDFGaussian measurementGaussian(const mrpt::poses::CPose2D& mean, const Eigen::Matrix3d& information);

/** The edge i -> j with measurement `z`, where i is held at `from_attachment` (its pose seen
 * from its anchor a) and j at `to_attachment` (seen from its anchor b), either one null when
 * that end is not merged: the edge a -> b (or a -> j, i -> b), mean
 * from_attachment (+) z (+) to_attachment^-1 and the covariance of that composition, the
 * three measurements taken as independent. */
mrpt::poses::CPosePDFGaussianInf carryEdge(const mrpt::poses::CPosePDFGaussianInf* from_attachment,
                                           const mrpt::poses::CPosePDFGaussianInf& z,
                                           const mrpt::poses::CPosePDFGaussianInf* to_attachment);

/** Two measurements of the same relative pose, one if they agree: the squared Mahalanobis
 * distance between them (their covariances summed) is at most `gate`. They are fused by
 * covariance intersection (Julier and Uhlmann 1997), linearized at `a`: information
 * w Ia + (1 - w) Ib, the w of largest determinant (0.5 on a tie), and the mean weighted alike.
 * Matches of the same two scans on every lap are not independent (their errors come from the
 * same geometry), and covariance intersection stays consistent whatever their correlation:
 * a revisit's carried edges between the same two nodes stay one edge, no more certain than
 * the best of them. None when they disagree (both stay, for the robust kernel to weigh). */
std::optional<mrpt::poses::CPosePDFGaussianInf> fuseAgreeing(const mrpt::poses::CPosePDFGaussianInf& a,
                                                             const mrpt::poses::CPosePDFGaussianInf& b, double gate);

/** The gate of fuseAgreeing for carried edges: chi-square, three degrees of freedom, 0.99. */
inline constexpr double kFuseGate = 11.34;

}  // namespace swslam::graph

#pragma once
// A starting point for a whole pose graph that does not depend on the drift of its guess
// (doc/graph-optimization.md, "Starting point"): LAGO (Carlone et al., "A fast and accurate
// approximation for planar pose graph optimization", IJRR 2014). The headings first, globally,
// by linear least squares on the edges' relative rotations, each unwrapped by the multiple of
// 2 pi that agrees with the spanning tree of the least heading variance; then the positions by linear least
// squares given those headings. Nonlinear least squares from there ends in the basin of the
// global optimum on the standard planar graphs, where it can fail from an odometry guess whose
// heading has drifted by tens of degrees.

#include <swslam/graph/optimizer.h>
#include <swslam/graph/truncated.h>

#include <vector>

namespace swslam::graph
{
/** The tree of the edges that reach every pose of the problem from its anchors (the fixed
 * poses, and the first pose of each connected component without one) along the paths of
 * least accumulated heading variance: per pose, the edge (index into problem.edges) that
 * reached it, -1 for an anchor. Deterministic (ties to the lower pose index). */
std::vector<int> spanningTree(const GraphProblem& problem);

/** Each edge's relative rotation unwrapped: z.theta plus the multiple of 2 pi that puts it
 * nearest the tree's headings (the anchors' headings composed along `tree`). */
std::vector<double> unwrappedRotations(const GraphProblem& problem, const std::vector<int>& tree);

/** LAGO's poses: the headings that minimize sum w (theta_j - theta_i - d_ij)^2 over the edges
 * (d the unwrapped rotations, w the inverse of the heading's variance from the edge's
 * information), the anchors' headings held; then the positions that minimize
 * sum |t_j - t_i - R(theta_i) z_ij|^2 under the edge's translation information turned by
 * theta_i, the anchors' positions held. Fixed poses keep their values, and so does the first
 * pose of each connected component without one. Throws std::invalid_argument for a problem
 * checkProblem() refuses. */
std::vector<geometry::Pose2> lagoPoses(const GraphProblem& problem);

/** LAGO's headings alone (the first of its two solves), per pose. */
std::vector<double> lagoHeadings(const GraphProblem& problem);

/** LAGO's second solve: the poses with those headings and the positions that fit them
 * (lagoPoses = lagoPositions(lagoHeadings)). */
std::vector<geometry::Pose2> lagoPositions(const GraphProblem& problem, const std::vector<double>& headings);

/** LAGO with the robustified edges decided by graduated non-convexity for truncated least
 * squares (truncated.h), each of its linear solves the non-minimal solver: the headings first,
 * their rotations unwrapped along the tree of the edges not robustified where those reach (the
 * odometry chain), a loop gated at chi-square 10.83 (one degree of freedom, 0.999, and an edge of
 * the chain in proportion to its larger gate); unwrapped again at the result and decided again
 * while that changes a multiple of 2 pi (twice at most); then the positions over the edges
 * whose heading was kept, a loop gated at 13.82 (two degrees). Edges
 * not in `use` take no part. Returns the poses and the robustified edges kept (and every edge
 * not robustified). */
struct RobustLago
{
  std::vector<geometry::Pose2> poses;
  std::vector<char> inliers;  ///< per edge
};
RobustLago robustLagoPoses(const GraphProblem& problem, const std::vector<char>& use, const OutlierGates& gates);

/** Optimizes a whole problem (optimizeGraphProblem) from its own poses and, when LAGO's poses
 * start at a lower cost under params' kernel than that run ended at (the guess was poor: an
 * odometry chain whose heading drifted, and it ended in a local minimum), from those too; the
 * result of the lower final cost stays, and report.lago_start says whether it is LAGO's. The
 * time and iterations are both runs' (LAGO's solve included). */
OptimizationReport optimizeFromBestStart(GraphProblem& problem, const GraphOptimizerParams& params);

}  // namespace swslam::graph

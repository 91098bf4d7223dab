#pragma once
// The robustified edges of a whole graph decided together (KernelSchedule::Tls;
// doc/graph-optimization.md, "Deciding the outliers"): the poses that minimize the truncated
// least-squares cost (truncated.h), and the edges beyond its gate. Several inlier sets are
// proposed, each by a method that does not depend on the others' weak spot, each is refined by
// least squares on its edges and then on the edges within the gate at the result (until that
// set holds), and the lowest truncated cost wins:
//  - every edge, when LAGO's headings fit every edge (a graph with no outlier);
//  - where loops are few, the loops taken one at a time in the chain's order, each kept if it
//    fits or clearly lowers the cost over the edges met so far (a sparse graph whose loops have
//    no neighbour to support them);
//  - the guess's: GNC for TLS from the guess, mu starting at 1 (an edge far from the guess
//    weighs nothing from the first round; from an odometry guess, a loop the chain cannot reach);
//  - the locally consistent loops (loop_support.h), from LAGO's poses on them;
//  - robust LAGO's (initialization.h) over the locally consistent loops (and over every loop
//    where few lack support).
// Then the best is tried with the edges switched off near their gates taken back, and without
// each strained run of loops that agree with each other.

#include <swslam/graph/optimizer.h>
#include <swslam/graph/truncated.h>

#include <string>
#include <vector>

namespace swslam::graph
{
/** The gates of params (outlier_gate for loops, ... for the chain). */
OutlierGates outlierGates(const GraphOptimizerParams& params);

/** Least squares on the edges flagged in `inliers` (and every edge not robustified) from the
 * problem's poses; then, while the set changes (5 rounds at most), on the edges within their
 * gate at the result. The poses take the result; `inliers` the last set. */
OptimizationReport refineInliers(GraphProblem& problem, std::vector<char>& inliers, const OutlierGates& gates,
                                 const GraphOptimizerParams& params);

/** The whole optimization (see the file's comment). report.start names the winning proposal,
 * report.switched_off lists the robustified edges beyond the gate. */
OptimizationReport optimizeTruncated(GraphProblem& problem, const GraphOptimizerParams& params);

}  // namespace swslam::graph

#pragma once
// Whether one robustified edge, switched from one side of its gate to the other, would lower the
// truncated least-squares cost (truncated.h) at a least-squares optimum of the edges kept: to
// first order, removing a kept edge lowers the optimal chi2 by e^T (S - J H^-1 J^T)^-1 e, adding
// a switched-off one raises it by e^T (S + J H^-1 J^T)^-1 e, with e its error, S its covariance
// (the inverse of its information), J its Jacobian and H the normal matrix of the kept edges
// (the deleted and the predicted residual of regression diagnostics). Where no single switch
// lowers the cost, the kept set is a local optimum of the truncated cost among the sets one
// switch away.

#include <swslam/graph/optimizer.h>
#include <swslam/graph/truncated.h>

#include <vector>

namespace swslam::graph
{
/** For each edge index in `candidates` (robustified edges of `problem`), the change of the
 * truncated cost if it were switched to the other side of its gate and the kept edges
 * re-optimized, to first order: for a kept edge (`kept[k]`), its gate's square less the drop of
 * the chi2 without it; for one switched off, the rise of the chi2 with it less its gate's square.
 * `problem.poses` must be the least-squares optimum of the kept edges (and every edge not
 * robustified). An edge whose ends the kept edges do not connect is free to add (a rise of 0);
 * one whose removal leaves its ends unconnected is fitted exactly and gains nothing by leaving
 * (a change of its gate's square). Throws std::runtime_error if the kept edges' normal matrix
 * cannot be factored. */
std::vector<double> singleFlipChanges(const GraphProblem& problem, const std::vector<char>& kept,
                                      const std::vector<size_t>& candidates, const OutlierGates& gates);

}  // namespace swslam::graph

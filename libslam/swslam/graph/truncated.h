#pragma once
// Truncated least squares (doc/graph-optimization.md, "Deciding the outliers"): a robustified
// edge costs its chi-square up to a gate and the gate's square beyond it, so that an outlier
// costs the same however wrong it is. Graduated non-convexity for it (Yang, Antonante, Tzoumas
// and Carlone, "Graduated non-convexity for robust spatial perception", RA-L 2020, eq. 11-12):
// weights from a surrogate whose non-convexity grows with mu, each round a weighted least
// squares solve, until the weights are 0 or 1.

#include <swslam/graph/optimizer.h>

#include <functional>
#include <vector>

namespace swslam::graph
{
/** The residual r = sqrt(e^T Omega e) beyond which a robustified edge is an outlier, by kind: a
 * loop's, and a larger one for an edge of the chain (consecutive, dense-neighbour, odometry
 * prior), which tracking gets wrong far more rarely than loop closing does. Switching it off
 * costs the square of its gate: were it the loops' gate, a graph could break its chain to take
 * in a run of false loops more cheaply than keep it. */
struct OutlierGates
{
  double loop = 5.0;
  double chain = 12.0;
  double of(const GraphProblem::Edge& e) const { return e.kind == EdgeKind::Loop ? loop : chain; }
};

/** The TLS surrogate's weight at squared residual r2 for the squared gate c2 and
 * non-convexity mu > 0: 1 within c2 mu / (mu + 1), 0 beyond c2 (mu + 1) / mu, between them
 * sqrt(c2 mu (mu + 1) / r2) - mu. */
double gncTlsWeight(double r2, double c2, double mu);

/** sum of e^T Omega e over the edges not robustified, plus min(e^T Omega e, gate^2) over the
 * robustified ones (each its kind's gate), at the problem's poses. */
double truncatedCost(const GraphProblem& problem, const OutlierGates& gates);

/** Mu grows by this factor each round (the paper's). */
constexpr double kGncMuFactor = 1.4;
/** Rounds at most. */
constexpr size_t kGncMaxRounds = 100;

/** GNC for TLS over residuals of which `robust` marks those weighed: `solve(w)` solves the
 * weighted problem (the others weigh 1), `squared(k)` is residual k's squared residual at its
 * solution (a residual of infinity is weighted 0 from the start), `c2[k]` its squared gate.
 * Starts at mu0 (<= 0: the paper's 1 / (2 max r2 / c2 - 1) after an unweighted solve) and
 * stops when every weight is 0 or 1. Returns the weights of the last solve. */
std::vector<double> graduatedTls(const std::vector<char>& robust, const std::vector<double>& c2, double mu0,
                                 const std::function<void(const std::vector<double>&)>& solve,
                                 const std::function<double(size_t)>& squared);

}  // namespace swslam::graph

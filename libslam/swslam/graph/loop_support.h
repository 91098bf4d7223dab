#pragma once
// Local consistency of loop closures (doc/graph-optimization.md, "Deciding the outliers"): two
// loops whose ends lie within a few nodes of each other along the odometry chain close a short
// cycle with it. If the cycle's error is within a chi-square gate of its covariance (the two
// loops' and the chain's between their ends, composed to first order), the two support each
// other. True loops come in runs, one revisit closing several, and support one another; a false
// loop between random nodes rarely has a neighbour that agrees with it.

#include <swslam/graph/optimizer.h>

#include <vector>

namespace swslam::graph
{
/** The odometry chain of a problem: its consecutive edges (EdgeKind::Consecutive) followed from
 * pose to pose. A problem may hold several chains (a gap, another session). */
struct OdometryChain
{
  std::vector<int> chain;     ///< per pose: which chain it is on (-1: none)
  std::vector<int> position;  ///< per pose: its index along its chain
  std::vector<int> next;      ///< per pose: the edge to the next pose of its chain (-1: the end)
  std::vector<int> previous;  ///< per pose: the edge from the previous pose (-1: the start)
};
OdometryChain odometryChain(const GraphProblem& problem);

/** Whether edge k is a loop closure candidate: robustified and not a step of the chain. */
bool isLoopCandidate(const GraphProblem& problem, const OdometryChain& chain, size_t k);

struct LoopSupportOptions
{
  int window = 10;       ///< [nodes] along the chain, at each end
  double gate = 16.27;   ///< chi-square of a cycle's error (3 degrees of freedom, 0.999)
};

/** The chi-square of the cycle that loops a (i -> j) and b (k -> l) close with the chain
 * (i to k, l to j, each at most options.window steps; a loop may run either way), or a
 * negative value if their ends do not lie on common chains within the window. */
double cycleChi2(const GraphProblem& problem, const OdometryChain& chain, size_t a, size_t b,
                 const LoopSupportOptions& options = {});

/** Which loop candidates agree with their neighbours (cycleChi2 within the gate), per edge:
 * - support: how many other loop candidates agree with it; -1 for an edge that is no loop
 *   candidate;
 * - runs: the run of loops it belongs to (-1: no loop candidate), loops joined when they agree
 *   (the loops of one revisit, or one group of false loops that agree), transitively; numbered
 *   from 0.
 * Each pair of neighbours is checked once, each edge's Gaussian built once. */
struct LoopAgreement
{
  std::vector<int> support;
  std::vector<int> runs;
};
LoopAgreement loopAgreement(const GraphProblem& problem, const OdometryChain& chain, const LoopSupportOptions& options = {});

}  // namespace swslam::graph

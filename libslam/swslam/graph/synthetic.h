#pragma once
// Synthetic pose graphs with a known truth, for tests and benchmarks: a Manhattan-like
// walk on a square grid (1 m steps, random 90 degree turns, kept inside a bounded area so
// that it keeps revisiting places), noisy odometry, dense-neighbour and loop edges, plus
// an optional share of wrong loop edges (random node pairs with a plausible-looking but
// false measurement).

#include <swslam/geometry/se2_error.h>
#include <swslam/graph/pose_graph.h>

#include <vector>

namespace swslam::graph
{
struct SyntheticGraphOptions
{
  size_t nodes = 638;
  size_t total_edges = 1952;     ///< target before wrong loops; fewer if candidates run out
  int grid_half_extent = 5;      ///< the walk stays in [-e, e]^2 grid cells
  size_t dense_neighbours = 1;   ///< node k also linked to k-2 .. k-1-dense_neighbours
  double sigma_xy = 0.05;        ///< [m] noise of every good measurement
  double sigma_theta = 0.01;     ///< [rad]
  double loop_radius = 1.5;      ///< [m] loop candidates: true distance below this
  size_t loop_min_gap = 5;       ///< loop candidates: node ids at least this far apart
  double wrong_loop_fraction = 0;  ///< wrong loops added, as a share of the good loops
  unsigned seed = 1;
};

struct SyntheticGraph
{
  PoseGraph graph;          ///< initial estimate: dead reckoning of the noisy odometry
  std::vector<geometry::Pose2> truth;  ///< indexed by node id 0..nodes-1
  size_t good_loops = 0, wrong_loops = 0;
};

/** Node k-1 -> k consecutive; k-2 -> k (and further back, see dense_neighbours)
 * dense-neighbour; then loops up to total_edges. */
SyntheticGraph makeGridWalkGraph(const SyntheticGraphOptions& options);

/** False loop closures added to a graph, as benchmarks of robust back ends do (Suenderhauf
 * and Protzel's Vertigo; ../shared/graphs/README.md): random node pairs at least `min_gap`
 * ids apart with a random measurement (x, y uniform in +-max_offset, theta uniform in +-pi),
 * or (grouped) runs of `group_size` consecutive pairs (i + t, j + t) sharing one measurement,
 * which agree with each other and so reinforce one another. */
struct FalseLoopOptions
{
  size_t count = 0;
  bool grouped = false;
  size_t group_size = 10;
  double max_offset = 10.0;  ///< [m] measured translation uniform in [-max_offset, max_offset]^2
  size_t min_gap = 10;       ///< the pair's node ids at least this far apart
  unsigned seed = 1;
};

/** Adds the false loops (kind Loop, with the information of the graph's median loop edge by
 * its trace, else of 5 cm and 0.6 degrees) and returns their edge indices. Throws
 * std::invalid_argument for a graph too small to hold a pair (or a run) min_gap apart. */
std::vector<size_t> addFalseLoops(PoseGraph& graph, const FalseLoopOptions& options);

/** The loop edges of a graph (its true loops, before false ones are added). */
size_t loopEdgeCount(const PoseGraph& graph);

struct TruthError
{
  double rmse_xy = 0, max_xy = 0;  ///< [m]
  double rmse_theta = 0;           ///< [rad]
};

/** The poses of a ground-truth graph whose node ids are 0..n-1, indexed by id (e.g. MRPT's
 * `*_groundtruth.graph`). Throws std::invalid_argument for other ids. */
std::vector<geometry::Pose2> truthFromGraph(const PoseGraph& graph);

/** Position and heading error of every node against `truth` (node id = index), with no
 * alignment: both share the gauge node's pose. Throws std::invalid_argument if a node id
 * has no truth. */
TruthError compareToTruth(const PoseGraph& graph, const std::vector<geometry::Pose2>& truth);

}  // namespace swslam::graph

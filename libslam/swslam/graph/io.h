#pragma once
// Pose-graph text files: MRPT's .graph, g2o and TORO (2D records).
//
// Read (the keyword of each line decides its layout, so one file may mix them):
//   VERTEX_SE2 id x y theta                              (g2o; what MRPT writes)
//   VERTEX2 | VERTEX id x y theta                         (TORO; MRPT's sample graphs)
//   EDGE_SE2 from to dx dy dtheta  I11 I12 I13 I22 I23 I33          (g2o order)
//   EDGE2 | EDGE from to dx dy dtheta  I11 I12 I22 I33 I13 I23       (TORO order:
//        inf_ff inf_fs inf_ss inf_rr inf_fr inf_sr, with f,s,r = x,y,theta)
//   FIX id                                                (gauge node; the first one counts)
// (dx, dy, dtheta) is the pose of `to` in the frame of `from`. Text after '#' or '|' is a
// comment; an edge comment "kind=<name>" (consecutive, dense_neighbour, loop,
// odometry_prior) sets the edge kind, otherwise to == from + 1 is consecutive and any other
// edge a loop; "switched_off" in it lists the edge in GraphLoadReport::switched_off;
// "kind=merged" merges `to` into `from` (PoseGraph::merge; applied after the other edges).
//
// Skipped with a count and the line numbers: blank and comment lines (not counted), lines
// with an unknown keyword or unparseable fields, EQUIV lines (node merging is not
// supported), FIX lines after the first. A vertex that only edges name (an edge-only g2o file)
// is placed from them: along the odometry chain (to == from + 1) from a placed vertex, through
// other edges where the chain breaks, and at the origin as a piece of its own where no edge
// reaches it; GraphLoadReport says how many were placed, and in how many pieces. Errors
// (std::runtime_error naming the file and line): a duplicate vertex id, a non-finite value,
// an edge from a vertex to itself, an information matrix that is not positive definite, FIX
// of a missing vertex, a file with no vertex and no edge.
//
// Written: g2o form (VERTEX_SE2, FIX root, EDGE_SE2 ... # kind=<name>, and " switched_off" for
// an edge the robust kernel switched off; then each merged node's attachment, # kind=merged),
// full precision, which MRPT, g2o and this reader all load.

#include <swslam/graph/pose_graph.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace swslam::graph
{
struct GraphLoadReport
{
  size_t vertices = 0, edges = 0;
  size_t skipped_lines = 0;
  std::vector<size_t> skipped_line_numbers;  ///< all of them, 1-based
  std::vector<std::string> skip_reasons;     ///< parallel to skipped_line_numbers
  std::vector<size_t> switched_off;          ///< indices of the edges marked " switched_off"
  size_t placed_vertices = 0;  ///< vertices no VERTEX line gave, placed from the edges
  size_t placed_pieces = 0;    ///< of them, pieces no edge joins to a vertex placed before (at the origin)
};

/** Reads a graph from `in`; `source` names it in messages. */
PoseGraph readGraph(std::istream& in, const std::string& source, GraphLoadReport* report = nullptr);
/** Reads a graph file; throws std::runtime_error if it cannot be opened. */
PoseGraph loadGraph(const std::string& path, GraphLoadReport* report = nullptr);

void writeGraph(const PoseGraph& graph, std::ostream& out, const std::vector<size_t>& switched_off = {});
/** Writes the graph in g2o form, atomically. */
void saveGraph(const PoseGraph& graph, const std::string& path, const std::vector<size_t>& switched_off = {});

}  // namespace swslam::graph

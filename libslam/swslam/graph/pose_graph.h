#pragma once
// The pose graph: a thin wrapper around mrpt::graphs::CNetworkOfPoses2DInf that adds, per
// edge, the kind of constraint (which decides whether it is robustified) and, per node,
// the list of its edges, so that a window of nodes finds its edges without scanning the
// whole graph, and the nodes merged into others (node_merge.h). Every pose and edge is
// validated on insertion.

#include <swslam/graph/edge_kind.h>

#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPosePDFGaussianInf.h>

#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace swslam::graph
{
class PoseGraph
{
 public:
  using TNodeID = mrpt::graphs::TNodeID;
  using Network = mrpt::graphs::CNetworkOfPoses2DInf;

  struct Edge
  {
    TNodeID from, to;
    EdgeKind kind;
    const mrpt::poses::CPosePDFGaussianInf* measurement;  ///< pose of `to` seen from `from`
  };

  PoseGraph() = default;
  PoseGraph(const PoseGraph& other);
  PoseGraph& operator=(const PoseGraph& other);
  PoseGraph(PoseGraph&&) = default;  // multimap nodes move with their addresses
  PoseGraph& operator=(PoseGraph&&) = default;

  /** Adds a node; throws std::invalid_argument on a non-finite pose or a duplicate id.
   * The first node added becomes the root (the gauge of full optimizations). */
  void addNode(TNodeID id, const mrpt::poses::CPose2D& pose);

  /** Adds an edge and returns its index; throws std::invalid_argument naming the problem
   * if a node is missing, from == to, the mean is not finite, or the information matrix
   * is not finite, not symmetric or not positive definite. An edge naming a merged node is
   * carried to its anchor (carryEdge); one that then joins a node to itself is not added
   * (nothing returned), and one that agrees with an edge of its kind between the same nodes
   * (same direction) is fused into it (fuseAgreeing; that edge's index returned). */
  std::optional<size_t> addEdge(TNodeID from, TNodeID to, const mrpt::poses::CPosePDFGaussianInf& z,
                                EdgeKind kind);

  /** Where a merged node is held: `z` is its pose seen from `anchor`. */
  struct Attachment
  {
    TNodeID anchor;
    mrpt::poses::CPosePDFGaussianInf z;
  };
  /** Merges node `id` into `anchor`: `id` is no longer optimized, its pose is anchor's
   * composed with z, and its edges, as every later edge that names it, are carried to
   * `anchor` (those that would join `anchor` to itself are dropped). Edge indices change.
   * Throws std::invalid_argument if a node is missing, id == anchor, `id` is merged already
   * or anchors a merged node, `anchor` is merged, the root would be merged, or z is not
   * finite with a positive-definite information. */
  void merge(TNodeID id, TNodeID anchor, const mrpt::poses::CPosePDFGaussianInf& z);
  bool isMerged(TNodeID id) const { return merged_.count(id) != 0; }
  /** Whether other nodes are merged into `id` (it cannot be merged itself then). */
  bool isAnchor(TNodeID id) const { return anchored_.count(id) != 0; }
  const std::map<TNodeID, Attachment>& merged() const { return merged_; }
  /** Nodes not merged into another. */
  size_t liveNodeCount() const { return nodeCount() - merged_.size(); }
  /** Places the nodes merged into `anchor` at its pose composed with their attachments (after
   * it moved). */
  void placeMergedInto(TNodeID anchor);

  bool hasNode(TNodeID id) const { return adjacency_.count(id) != 0; }
  const mrpt::poses::CPose2D& pose(TNodeID id) const;
  /** Throws std::invalid_argument for a missing node or a non-finite pose. */
  void setPose(TNodeID id, const mrpt::poses::CPose2D& pose);

  size_t nodeCount() const { return net_.nodes.size(); }
  size_t edgeCount() const { return edges_.size(); }
  const Edge& edge(size_t index) const { return edges_.at(index); }
  /** Indices of the edges touching node `id` (both directions; none for a merged node). */
  const std::vector<size_t>& edgesOf(TNodeID id) const;

  TNodeID root() const { return net_.root; }
  void setRoot(TNodeID id);

  /** The newest `n` node ids (highest ids), oldest first, merged ones included. */
  std::vector<TNodeID> newestNodes(size_t n) const;
  /** All node ids in increasing order. */
  std::vector<TNodeID> nodeIds() const;

  /** The underlying MRPT graph (for MRPT's tools: its optimizer, viewers, I/O). */
  const Network& network() const { return net_; }

 private:
  /** After copying `other`, points edges_ at this graph's own measurements. */
  void relinkEdges(const PoseGraph& other);
  /** Removes edge `index`; the last edge takes its index. */
  void removeEdge(size_t index);

  Network net_;
  std::vector<Edge> edges_;
  std::unordered_map<TNodeID, std::vector<size_t>> adjacency_;
  std::map<TNodeID, Attachment> merged_;
  std::unordered_map<TNodeID, std::vector<TNodeID>> anchored_;  ///< the nodes merged into each anchor
};

/** Throws std::invalid_argument(`what` + reason) unless `info` is finite, symmetric and
 * positive definite. */
void checkInformationMatrix(const mrpt::math::CMatrixDouble33& info, const std::string& what);

}  // namespace swslam::graph

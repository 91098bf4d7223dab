#include <swslam/graph/pose_graph.h>

#include <swslam/graph/node_merge.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swslam::graph
{
namespace
{

bool finitePose(const mrpt::poses::CPose2D& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.phi());
}

std::string nodeName(PoseGraph::TNodeID id) { return "node " + std::to_string(id); }
}  // namespace

void checkInformationMatrix(const mrpt::math::CMatrixDouble33& info, const std::string& what)
{
  const Eigen::Matrix3d m = info.asEigen();
  if (!m.allFinite()) throw std::invalid_argument(what + ": information matrix is not finite");
  const double scale = std::max(1.0, m.cwiseAbs().maxCoeff());
  if ((m - m.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale)
    throw std::invalid_argument(what + ": information matrix is not symmetric");
  Eigen::LLT<Eigen::Matrix3d> llt(m);
  if (llt.info() != Eigen::Success)
    throw std::invalid_argument(what + ": information matrix is not positive definite");
}

PoseGraph::PoseGraph(const PoseGraph& other)
    : net_(other.net_), edges_(other.edges_), adjacency_(other.adjacency_), merged_(other.merged_),
      anchored_(other.anchored_)
{
  relinkEdges(other);
}

PoseGraph& PoseGraph::operator=(const PoseGraph& other)
{
  if (this != &other)
  {
    net_ = other.net_;
    edges_ = other.edges_;
    adjacency_ = other.adjacency_;
    merged_ = other.merged_;
    anchored_ = other.anchored_;
    relinkEdges(other);
  }
  return *this;
}

void PoseGraph::relinkEdges(const PoseGraph& other)
{
  // A copied multimap keeps the order of its elements: walk both in step.
  std::unordered_map<const mrpt::poses::CPosePDFGaussianInf*, const mrpt::poses::CPosePDFGaussianInf*>
      moved;
  moved.reserve(edges_.size());
  auto mine = net_.edges.begin();
  for (auto theirs = other.net_.edges.begin(); theirs != other.net_.edges.end(); ++theirs, ++mine)
    moved[&theirs->second] = &mine->second;
  for (auto& e : edges_) e.measurement = moved.at(e.measurement);
}

void PoseGraph::addNode(TNodeID id, const mrpt::poses::CPose2D& pose)
{
  if (!finitePose(pose)) throw std::invalid_argument(nodeName(id) + ": pose is not finite");
  if (hasNode(id)) throw std::invalid_argument(nodeName(id) + ": duplicate node id");
  if (net_.nodes.empty()) net_.root = id;
  net_.nodes[id] = pose;
  adjacency_[id];
}

std::optional<size_t> PoseGraph::addEdge(TNodeID from, TNodeID to, const mrpt::poses::CPosePDFGaussianInf& z,
                                         EdgeKind kind)
{
  const std::string what = "edge " + std::to_string(from) + " -> " + std::to_string(to);
  if (!hasNode(from)) throw std::invalid_argument(what + ": missing " + nodeName(from));
  if (!hasNode(to)) throw std::invalid_argument(what + ": missing " + nodeName(to));
  if (from == to) throw std::invalid_argument(what + ": an edge must join two different nodes");
  if (!finitePose(z.mean)) throw std::invalid_argument(what + ": measurement is not finite");
  checkInformationMatrix(z.cov_inv, what);
  const auto from_merged = merged_.find(from), to_merged = merged_.find(to);
  if (from_merged == merged_.end() && to_merged == merged_.end())
  {
    const auto it = net_.edges.emplace(std::make_pair(from, to), z);
    edges_.push_back(Edge{from, to, kind, &it->second});
    adjacency_[from].push_back(edges_.size() - 1);
    adjacency_[to].push_back(edges_.size() - 1);
    return edges_.size() - 1;
  }
  const TNodeID a = from_merged == merged_.end() ? from : from_merged->second.anchor;
  const TNodeID b = to_merged == merged_.end() ? to : to_merged->second.anchor;
  if (a == b) return std::nullopt;
  const mrpt::poses::CPosePDFGaussianInf carried =
      carryEdge(from_merged == merged_.end() ? nullptr : &from_merged->second.z, z,
                to_merged == merged_.end() ? nullptr : &to_merged->second.z);
  // Into an edge of the same kind between the same nodes that it agrees with: revisits then
  // add information, not edges.
  for (const size_t k : adjacency_[a])
  {
    const Edge& e = edges_[k];
    if (e.from != a || e.to != b || e.kind != kind) continue;
    if (const auto fused = fuseAgreeing(*e.measurement, carried, kFuseGate))
    {
      auto [first, last] = net_.edges.equal_range(std::make_pair(a, b));
      for (; first != last; ++first)
        if (&first->second == e.measurement) first->second = *fused;
      return k;
    }
  }
  return addEdge(a, b, carried, kind);
}

void PoseGraph::removeEdge(size_t index)
{
  const Edge removed = edges_.at(index);
  auto [first, last] = net_.edges.equal_range(std::make_pair(removed.from, removed.to));
  for (; first != last; ++first)
    if (&first->second == removed.measurement)
    {
      net_.edges.erase(first);
      break;
    }
  auto forget = [this](TNodeID node, size_t k) {
    auto& list = adjacency_[node];
    list.erase(std::find(list.begin(), list.end(), k));
  };
  forget(removed.from, index);
  forget(removed.to, index);
  const size_t moved = edges_.size() - 1;
  if (moved != index)
  {
    edges_[index] = edges_[moved];
    for (const TNodeID node : {edges_[index].from, edges_[index].to})
      for (size_t& k : adjacency_[node])
        if (k == moved) k = index;
  }
  edges_.pop_back();
}

void PoseGraph::merge(TNodeID id, TNodeID anchor, const mrpt::poses::CPosePDFGaussianInf& z)
{
  const std::string what = "merging " + nodeName(id) + " into " + nodeName(anchor);
  if (!hasNode(id) || !hasNode(anchor)) throw std::invalid_argument(what + ": missing node");
  if (id == anchor) throw std::invalid_argument(what + ": a node cannot be merged into itself");
  if (isMerged(id)) throw std::invalid_argument(what + ": it is merged already");
  if (anchored_.count(id)) throw std::invalid_argument(what + ": other nodes are merged into it");
  if (isMerged(anchor)) throw std::invalid_argument(what + ": the anchor is merged itself");
  if (id == root()) throw std::invalid_argument(what + ": the root (gauge) stays a node");
  if (!finitePose(z.mean)) throw std::invalid_argument(what + ": attachment is not finite");
  checkInformationMatrix(z.cov_inv, what);
  struct Carried
  {
    TNodeID from, to;
    mrpt::poses::CPosePDFGaussianInf z;
    EdgeKind kind;
  };
  std::vector<Carried> carried;
  while (!adjacency_[id].empty())
  {
    const size_t k = adjacency_[id].back();
    const Edge& e = edges_[k];
    carried.push_back({e.from, e.to, *e.measurement, e.kind});
    removeEdge(k);
  }
  merged_.emplace(id, Attachment{anchor, z});
  anchored_[anchor].push_back(id);
  net_.nodes[id] = pose(anchor) + z.mean;
  for (auto it = carried.rbegin(); it != carried.rend(); ++it) addEdge(it->from, it->to, it->z, it->kind);
}

void PoseGraph::placeMergedInto(TNodeID anchor)
{
  const auto it = anchored_.find(anchor);
  if (it == anchored_.end()) return;
  const mrpt::poses::CPose2D& at = pose(anchor);
  for (const TNodeID id : it->second) net_.nodes[id] = at + merged_.at(id).z.mean;
}

const mrpt::poses::CPose2D& PoseGraph::pose(TNodeID id) const
{
  const auto it = net_.nodes.find(id);
  if (it == net_.nodes.end()) throw std::invalid_argument(nodeName(id) + ": no such node");
  return it->second;
}

void PoseGraph::setPose(TNodeID id, const mrpt::poses::CPose2D& pose)
{
  const auto it = net_.nodes.find(id);
  if (it == net_.nodes.end()) throw std::invalid_argument(nodeName(id) + ": no such node");
  if (!finitePose(pose)) throw std::invalid_argument(nodeName(id) + ": pose is not finite");
  it->second = pose;
}

const std::vector<size_t>& PoseGraph::edgesOf(TNodeID id) const
{
  const auto it = adjacency_.find(id);
  if (it == adjacency_.end()) throw std::invalid_argument(nodeName(id) + ": no such node");
  return it->second;
}

void PoseGraph::setRoot(TNodeID id)
{
  if (!hasNode(id)) throw std::invalid_argument("root: missing " + nodeName(id));
  if (isMerged(id)) throw std::invalid_argument("root: " + nodeName(id) + " is merged into another");
  net_.root = id;
}

std::vector<PoseGraph::TNodeID> PoseGraph::newestNodes(size_t n) const
{
  std::vector<TNodeID> ids;
  for (auto it = net_.nodes.rbegin(); it != net_.nodes.rend() && ids.size() < n; ++it)
    ids.push_back(it->first);
  return {ids.rbegin(), ids.rend()};
}

std::vector<PoseGraph::TNodeID> PoseGraph::nodeIds() const
{
  std::vector<TNodeID> ids;
  ids.reserve(net_.nodes.size());
  for (const auto& n : net_.nodes) ids.push_back(n.first);
  return ids;
}

}  // namespace swslam::graph

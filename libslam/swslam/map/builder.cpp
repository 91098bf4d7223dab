#include <swslam/map/builder.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace swslam::map
{
MapBuilder::MapBuilder(const MapParams& params)
    : params_(params), grid_(params.resolution, params.initial_half_size, params.grow_margin)
{
}

void MapBuilder::insert(MapNodeId id, const mrpt::obs::CObservation2DRangeScan& scan,
                        const mrpt::poses::CPose2D& vehicle_pose)
{
  std::lock_guard<std::mutex> write(write_mutex_);
  if (nodes_.count(id))
    throw std::invalid_argument("map: node " + std::to_string(id) + " is already inserted");
  const mrpt::obs::CObservation2DRangeScan sanitized = sanitizedScan(scan, params_);
  const ScanContribution contribution = computeContribution(sanitized, vehicle_pose, params_, scratch_);
  Node node{StoredScan(sanitized), vehicle_pose};
  {
    std::lock_guard<std::mutex> lock(grid_mutex_);
    grid_.add(contribution, +1);
  }
  nodes_.emplace(id, std::move(node));
}

void MapBuilder::update(MapNodeId id, const mrpt::poses::CPose2D& new_pose)
{
  reinsertMoved({{id, new_pose}}, geometry::MoveThreshold{-1, -1});
}

void MapBuilder::remove(MapNodeId id)
{
  std::lock_guard<std::mutex> write(write_mutex_);
  const auto it = nodes_.find(id);
  if (it == nodes_.end()) throw std::invalid_argument("map: unknown node " + std::to_string(id));
  const ScanContribution contribution =
      computeContribution(it->second.scan.restore(), it->second.pose, params_, scratch_);
  {
    std::lock_guard<std::mutex> lock(grid_mutex_);
    grid_.add(contribution, -1);
  }
  nodes_.erase(it);
}

ReinsertReport MapBuilder::reinsertMoved(const std::map<MapNodeId, mrpt::poses::CPose2D>& poses,
                                         const geometry::MoveThreshold& threshold)
{
  std::lock_guard<std::mutex> write(write_mutex_);
  ReinsertReport report;
  // Ray tracing first, without holding the grid: readers keep reading the old map. A node's
  // old contribution is traced again from its scan at its old pose (the same deltas as when it
  // was added: computeContribution is deterministic), so that no node keeps its own.
  SumsChange change;
  std::vector<std::pair<Node*, mrpt::poses::CPose2D>> moved;
  for (const auto& [id, pose] : poses)
  {
    if (!std::isfinite(pose.x()) || !std::isfinite(pose.y()) || !std::isfinite(pose.phi()))
      throw std::invalid_argument("map: node " + std::to_string(id) + " pose " +
                                  pose.asString() + " is not finite");
    const auto it = nodes_.find(id);
    if (it == nodes_.end())
    {
      report.unknown++;
      continue;
    }
    if (!geometry::movedBeyond(it->second.pose, pose, threshold))
    {
      report.unchanged++;
      continue;
    }
    Node& node = it->second;
    const mrpt::obs::CObservation2DRangeScan scan = node.scan.restore();
    change.add(computeContribution(scan, node.pose, params_, scratch_), -1);
    change.add(computeContribution(scan, pose, params_, scratch_), +1);
    moved.emplace_back(&node, pose);
    report.moved++;
  }
  if (poses.size() == 1 && report.unknown == 1)
    throw std::invalid_argument("map: unknown node " + std::to_string(poses.begin()->first));

  std::lock_guard<std::mutex> lock(grid_mutex_);
  grid_.apply(change);
  for (auto& [node, pose] : moved) node->pose = pose;
  return report;
}

mrpt::maps::COccupancyGridMap2D MapBuilder::snapshot() const
{
  std::lock_guard<std::mutex> lock(grid_mutex_);
  return grid_.grid();
}

mrpt::poses::CPose2D MapBuilder::nodePose(MapNodeId id) const
{
  std::lock_guard<std::mutex> write(write_mutex_);
  const auto it = nodes_.find(id);
  if (it == nodes_.end()) throw std::invalid_argument("map: unknown node " + std::to_string(id));
  return it->second.pose;
}

size_t MapBuilder::nodeCount() const
{
  std::lock_guard<std::mutex> write(write_mutex_);
  return nodes_.size();
}

int32_t MapBuilder::cellSum(int x, int y) const
{
  std::lock_guard<std::mutex> lock(grid_mutex_);
  return grid_.sum(x, y);
}

CellBox MapBuilder::cellBox() const
{
  std::lock_guard<std::mutex> lock(grid_mutex_);
  return grid_.box();
}

size_t MapBuilder::bytes() const
{
  std::lock_guard<std::mutex> write(write_mutex_);
  size_t b = 0;
  for (const auto& [id, node] : nodes_) b += node.scan.bytes();
  std::lock_guard<std::mutex> lock(grid_mutex_);
  return b + grid_.bytes();
}

}  // namespace swslam::map

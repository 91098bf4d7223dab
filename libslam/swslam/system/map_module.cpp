#include <swslam/system/map_module.h>

namespace swslam::system
{
MapModule::MapModule(const map::MapParams& params) : builder_(params) {}

MapStep MapModule::handle(const MapMessage& message)
{
  MapStep step;
  if (const auto* ins = std::get_if<MapInsert>(&message))
  {
    step.scan = ins->scan;
    builder_.insert(ins->id, *ins->observation, ins->pose);
    step.inserted = 1;
  }
  else
  {
    const auto& re = std::get<MapReinsert>(message);
    step.scan = re.scan;
    for (const map::MapNodeId id : re.removed) builder_.remove(id);
    step.reinserted = builder_.reinsertMoved(re.poses, builder_.params().reinsertThreshold());
  }
  return step;
}

void MapModule::merge(MapReinsert& into, MapReinsert&& later)
{
  into.removed.insert(into.removed.end(), later.removed.begin(), later.removed.end());
  for (const map::MapNodeId id : later.removed) into.poses.erase(id);
  for (auto& [id, pose] : later.poses) into.poses[id] = pose;
  into.scan = later.scan;
}

}  // namespace swslam::system

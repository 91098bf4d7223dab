#pragma once
// The map construction module (paper Fig. 1, sec. IV): inserts each new node's scan and, after
// an optimization, re-inserts the scans of nodes that moved. The grid is readable (snapshot)
// from any thread while this module's thread keeps changing it.

#include <swslam/map/builder.h>
#include <swslam/system/messages.h>

namespace swslam::system
{
/** What one map step did. */
struct MapStep
{
  size_t scan = 0;
  size_t inserted = 0;
  map::ReinsertReport reinserted;
};

class MapModule
{
 public:
  explicit MapModule(const map::MapParams& params);

  MapStep handle(const MapMessage& message);

  /** Merges a later re-insertion into an earlier one (the later poses win), so that a map
   * thread that fell behind does the work once. */
  static void merge(MapReinsert& into, MapReinsert&& later);

  const map::MapBuilder& builder() const { return builder_; }

 private:
  map::MapBuilder builder_;
};

}  // namespace swslam::system

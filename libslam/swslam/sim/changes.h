#pragma once
// A changed world for a later survey (scenario [changes]): rocks taken away from, and rocks put
// on, the water within a band around the path, so that a second run over the same waypoints
// sees a place that changed. The changes are written as NAME.changes.csv (kind, x, y, radius
// in the world frame) for scoring a change report.

#include <swslam/sim/scenario.h>
#include <swslam/sim/vehicle.h>
#include <swslam/sim/world.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace swslam::sim
{
struct WorldChange
{
  bool added = false;  ///< put (else taken away)
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double radius = 0;
};

/** Applies `p` to `world` (deterministic in p.seed); returns the changes, removals first.
 * Throws std::invalid_argument naming [changes] if the band holds fewer rocks of radius
 * >= 0.5 m than p.remove, or if no free water is found for a rock to put. */
std::vector<WorldChange> applyChanges(World& world, const ChangesParams& p, const VehiclePath& path);

/** Writes the changes as CSV (header "kind,x,y,radius"; kind "removed" or "added"), atomically. */
void writeChanges(const std::string& path, const std::vector<WorldChange>& changes);

}  // namespace swslam::sim

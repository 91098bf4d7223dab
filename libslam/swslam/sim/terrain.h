#pragma once
// Procedural generation of a natural world from a scenario and a seed: an irregular
// lake shore (and island) as a low bank facing the water, rocks in the water, tree
// trunks and bushes on the banks, reed clusters in the shallows, and a clear lane along
// the vehicle's path.

#include <swslam/sim/scenario.h>
#include <swslam/sim/vehicle.h>
#include <swslam/sim/world.h>

namespace swslam::sim
{
/** Generates the world of `sc` (same seed, same world) around `path`. */
World generateWorld(const Scenario& sc, const VehiclePath& path);

/** Throws std::invalid_argument naming the problem if the path leaves the world,
 * crosses onto land (when there is water) or turns faster than the vehicle can. */
void checkPathFits(const Scenario& sc, const World& world, const VehiclePath& path);

}  // namespace swslam::sim

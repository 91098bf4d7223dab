#pragma once
// A scenario's values checked before anything is simulated.

#include <swslam/sim/scenario.h>

namespace swslam::sim
{
/** Checks values (ranges, sensor geometry) without the world; throws naming the key. */
void validateScenario(const Scenario& s);

}  // namespace swslam::sim

#include <swslam/app/sim_run.h>

#include <swslam/app/exit_codes.h>
#include <swslam/sim/scenario.h>
#include <swslam/sim/simulator.h>

#include <ostream>

namespace swslam::app
{
int runSim(const SimOptions& o, std::ostream& out, std::ostream& err)
{
  return exitCodeOf("swslam-sim", err, [&] {
    const auto summary = sim::runSimulation(sim::loadScenario(o.scenario), o.output);
    if (o.summary) out << sim::formatSummary(summary);
    return kExitOk;
  });
}

}  // namespace swslam::app

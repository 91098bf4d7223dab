// swslam-sim: generates a natural-environment dataset (rawlog, ground truth, world
// picture) from a scenario file. See doc/simulator.md.
#include "cli.h"
#include <swslam/sim/scenario.h>
#include <swslam/sim/simulator.h>


#include <exception>
#include <iostream>

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-sim: simulated 2D LiDAR datasets of natural places", ' ', "0.1");
  TCLAP::ValueArg<std::string> scenario("s", "scenario", "Scenario .ini file", true, "",
                                        "FILE.ini", cmd);
  TCLAP::ValueArg<std::string> output("o", "output", "Output directory (created if missing)",
                                      true, "", "DIR", cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "Do not print the summary", cmd);
  try
  {
    if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;
    const auto sc = swslam::sim::loadScenario(scenario.getValue());
    const auto summary = swslam::sim::runSimulation(sc, output.getValue());
    if (!quiet.getValue()) std::cout << swslam::sim::formatSummary(summary);
    return 0;
  }
  catch (const TCLAP::ArgException& e)
  {
    std::cerr << "swslam-sim: " << e.error() << " (" << e.argId() << ")\n";
  }
  catch (const std::exception& e)
  {
    std::cerr << "swslam-sim: " << e.what() << "\n";
  }
  return 1;
}

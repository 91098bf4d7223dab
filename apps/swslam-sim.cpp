// swslam-sim: generates a natural-environment dataset (rawlog, ground truth, world
// picture) from a scenario file. See doc/simulator.md.
#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-sim: simulated 2D LiDAR datasets of natural places", ' ', "0.1");
  TCLAP::ValueArg<std::string> scenario("s", "scenario", "Scenario .ini file", true, "",
                                        "FILE.ini", cmd);
  TCLAP::ValueArg<std::string> output("o", "output", "Output directory (created if missing)",
                                      true, "", "DIR", cmd);
  TCLAP::SwitchArg quiet("q", "quiet", "Do not print the summary", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

  swslam::app::SimOptions o;
  o.scenario = scenario.getValue();
  o.output = output.getValue();
  o.summary = !quiet.getValue();
  return SWSLAM_RUN_IN_LIBRARY("swslam-sim", swslam_run_sim, o);
}

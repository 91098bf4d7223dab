// swslam-regen-map: rebuilds a finished run's map from its graph and the input log, e.g. at
// 0.1 m for the offline map (see doc/system.md).
#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-regen-map: a run's map again, at another resolution", ' ', "0.1");
  TCLAP::ValueArg<std::string> run("r", "run", "Output directory of a swslam run (graph.graph, keyframes.tum)",
                                   true, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> input("i", "input", "The run's input log (default: the one its run.ini names)", false,
                                     "", "LOG", cmd);
  TCLAP::ValueArg<std::string> output("o", "output", "Where to write the map files", true, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> config("c", "config", "Configuration ([map], [carmen]; default: the run's run.ini, "
                                      "else the installed config/default.ini)", false, "", "INI", cmd);
  TCLAP::ValueArg<double> resolution("", "resolution", "Cell size [m] (default: the config's)", false, 0, "M", cmd);
  TCLAP::SwitchArg no_render("", "no-render", "Skip render.png", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

  swslam::app::RegenMapOptions o;
  o.run = run.getValue();
  o.input = input.getValue();
  o.output = output.getValue();
  o.config = config.getValue();
  if (resolution.isSet()) o.resolution = resolution.getValue();
  o.render = !no_render.getValue();
  return SWSLAM_RUN_IN_LIBRARY("swslam-regen-map", swslam_run_regen_map, o);
}

// swslam-regen-map: rebuilds a finished run's map from its graph and the input log, e.g. at
// 0.1 m for the offline map (see doc/system.md).
#include "cli.h"

#include <swslam/app/config.h>
#include <swslam/app/default_config.h>
#include <swslam/app/regen_map.h>
#include <swslam/app/run_outputs.h>
#include <swslam/graph/io.h>
#include <swslam/map/outputs.h>
#include <swslam/system/config.h>

#include <filesystem>
#include <iostream>

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-regen-map: a run's map again, at another resolution", ' ', "0.1");
  TCLAP::ValueArg<std::string> run("r", "run", "Output directory of a swslam run (graph.graph, keyframes.tum)",
                                   true, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> input("i", "input", "The run's input log", true, "", "LOG", cmd);
  TCLAP::ValueArg<std::string> output("o", "output", "Where to write the map files", true, "", "DIR", cmd);
  TCLAP::ValueArg<std::string> config("c", "config", "Configuration ([map], [carmen]; default: the installed "
                                      "config/default.ini)", false, "", "INI", cmd);
  TCLAP::ValueArg<double> resolution("", "resolution", "Cell size [m] (default: the config's)", false, 0, "M", cmd);
  TCLAP::SwitchArg no_render("", "no-render", "Skip render.png", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;
  try
  {
    swslam::app::Config loaded = swslam::app::loadConfig(swslam::app::configOrDefault(config.getValue()));
    swslam::system::SystemParams& params = loaded.system;
    if (resolution.isSet())
    {
      params.map.resolution = resolution.getValue();
      try
      {
        swslam::map::MapParams::table().check(params.map);
      }
      catch (const std::invalid_argument& e)
      {
        throw std::invalid_argument("--resolution " + std::to_string(resolution.getValue()) + ": " + e.what());
      }
    }
    swslam::system::RunResults run_data;
    swslam::graph::GraphLoadReport load;
    run_data.graph = swslam::graph::loadGraph(run.getValue() + "/graph.graph", &load);
    for (size_t k = 0; k < load.skipped_lines; ++k)
      std::cerr << "swslam-regen-map: graph.graph line " << load.skipped_line_numbers[k]
                << " skipped: " << load.skip_reasons[k] << "\n";
    run_data.switched_off = load.switched_off;
    run_data.keyframes = swslam::common::readTum(run.getValue() + "/keyframes.tum");
    // The pictures draw the run's every-scan trajectory when it is there, else the keyframes.
    const std::string every_scan = run.getValue() + "/trajectory.tum";
    const bool has_every_scan = std::filesystem::is_regular_file(every_scan);
    run_data.trajectory = has_every_scan ? swslam::common::readTum(every_scan) : run_data.keyframes;
    // ...and mark the scans the prediction placed, from the run's stats.csv (one row per pose).
    std::string stats_problem;
    if (has_every_scan)
      run_data.stats = swslam::app::statsForPictures(run.getValue() + "/stats.csv", run_data.trajectory.size(),
                                                     stats_problem);
    if (!stats_problem.empty())
      std::cerr << "swslam-regen-map: " << stats_problem << "; the pictures mark no scan as placed by the prediction\n";
    swslam::app::RegenReport report;
    const auto grid = swslam::app::regenerateMap(run_data.graph, run_data.keyframes, input.getValue(),
                                            params.map, loaded.carmen, &report);
    const auto problems = swslam::map::writeMapOutputs(output.getValue(), grid, params.map,
                                                       swslam::app::overlayOf(run_data), !no_render.getValue());
    for (const auto& p : problems) std::cerr << "swslam-regen-map: " << p.file << ": " << p.message << "\n";
    std::cout << report.inserted << " of " << report.nodes << " node scans inserted at "
              << params.map.resolution << " m; map files in " << output.getValue() << "/\n";
    return problems.empty() ? 0 : 4;
  }
  catch (const std::exception& e)
  {
    std::cerr << "swslam-regen-map: " << e.what() << "\n";
    return 1;
  }
}

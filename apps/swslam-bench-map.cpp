// Benchmark: map construction (insert, update, re-insertion after a loop) on a log with
// reference poses; optionally writes the map outputs of the result.
#include "cli.h"
#include <swslam/bench/map_builder.h>
#include <swslam/common/tum_io.h>
#include <swslam/map/outputs.h>
#include <swslam/app/config.h>


#include <iostream>

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-bench-map: map construction timings", ' ', "0.1");
  TCLAP::ValueArg<std::string> input("i", "input", "Rawlog with 2D scans", true, "", "LOG.rawlog", cmd);
  TCLAP::ValueArg<std::string> gt("g", "ground-truth", "Reference poses (TUM)", true, "", "GT.tum", cmd);
  TCLAP::ValueArg<size_t> every("n", "node-every", "One node every N scans", false, 20, "N", cmd);
  TCLAP::ValueArg<std::string> config("c", "config", "Config file ([map] section)", false, "", "INI", cmd);
  TCLAP::ValueArg<std::string> output("o", "output", "Write the map outputs here", false, "", "DIR", cmd);
  try
  {
    if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;
    swslam::map::MapParams params;
    if (!config.getValue().empty())
      params = swslam::app::loadConfig(config.getValue()).system.map;
    const auto data = swslam::io::loadScansWithTruth(input.getValue(), swslam::common::readTum(gt.getValue()));
    swslam::map::MapBuilder builder(params);
    const auto f = swslam::bench::benchmarkMapBuilder(data, every.getValue(), builder);
    std::cout << "# " << input.getValue() << ", resolution " << params.resolution << " m\n"
              << swslam::bench::formatFigures(f);
    if (!output.getValue().empty())
    {
      swslam::map::Overlay overlay;
      overlay.trajectory = data.truth;
      for (const auto& problem : swslam::map::writeMapOutputs(output.getValue(), builder.snapshot(), params, overlay))
        std::cerr << "swslam-bench-map: " << problem.file << ": " << problem.message << "\n";
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    std::cerr << "swslam-bench-map: " << e.what() << "\n";
    return 1;
  }
}

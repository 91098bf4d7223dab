// Benchmark: map construction (insert, update, re-insertion after a loop) on a log with
// reference poses; optionally writes the map outputs of the result.
#include "cli.h"
#include "programs.h"
#include "run_in_library.h"

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-bench-map: map construction timings", ' ', "0.1");
  TCLAP::ValueArg<std::string> input("i", "input", "Rawlog with 2D scans", true, "", "LOG.rawlog", cmd);
  TCLAP::ValueArg<std::string> gt("g", "ground-truth", "Reference poses (TUM)", true, "", "GT.tum", cmd);
  TCLAP::ValueArg<size_t> every("n", "node-every", "One node every N scans", false, 20, "N", cmd);
  TCLAP::ValueArg<std::string> config("c", "config", "Config file ([map] section)", false, "", "INI", cmd);
  TCLAP::ValueArg<std::string> output("o", "output", "Write the map outputs here", false, "", "DIR", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;

  swslam::app::BenchMapOptions o;
  o.input = input.getValue();
  o.ground_truth = gt.getValue();
  o.node_every = every.getValue();
  o.config = config.getValue();
  o.output = output.getValue();
  return SWSLAM_RUN_IN_LIBRARY("swslam-bench-map", swslam_run_bench_map, o);
}

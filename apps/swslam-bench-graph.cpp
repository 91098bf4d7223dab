// Benchmark of the pose-graph optimizer: ours vs MRPT's optimize_graph_spa_levmarq vs Ceres
// on the same graphs (time, final chi2 with the original information, error vs truth),
// the sliding-window update cost against graph size, and robust vs L2 under wrong loops.
#include "ceres_solver.h"
#include "cli.h"

#include <swslam/bench/graph.h>

#include <cstdio>

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-bench-graph", ' ', "0.1");
  TCLAP::ValueArg<std::string> datasets("", "mrpt-datasets", "MRPT datasets directory", false,
                                        "/usr/share/mrpt/datasets", "DIR", cmd);
  TCLAP::ValueArg<int> repeats("", "repeats", "timed runs per solver (median)", false, 5, "N", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;
  try
  {
    if (repeats.getValue() < 1) throw std::invalid_argument("--repeats must be >= 1");
    swslam::bench::runGraphBenchmark(datasets.getValue(), repeats.getValue(), runCeres);
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "swslam-bench-graph: %s\n", e.what());
    return 1;
  }
  return 0;
}

// Benchmark of the pose-graph optimizer: ours vs MRPT's optimize_graph_spa_levmarq vs Ceres
// on the same graphs (time, final chi2 with the original information, error vs truth),
// the sliding-window update cost against graph size, and robust vs L2 under wrong loops.
#include "cli.h"
#ifdef SWSLAM_WITH_CERES
#include "ceres_solver.h"
#endif

#include <swslam/bench/false_loops.h>
#include <swslam/bench/graph.h>
#include <swslam/graph/io.h>
#include <swslam/graph/synthetic.h>
#include <swslam/app/config.h>

#include <cmath>
#include <cstdio>
#include <fstream>

int main(int argc, char** argv)
{
  TCLAP::CmdLine cmd("swslam-bench-graph", ' ', "0.1");
  TCLAP::ValueArg<std::string> datasets("", "mrpt-datasets", "MRPT datasets directory", false,
                                        "/usr/share/mrpt/datasets", "DIR", cmd);
  TCLAP::ValueArg<int> repeats("", "repeats", "timed runs per solver (median)", false, 5, "N", cmd);
  TCLAP::ValueArg<unsigned> seed("", "seed", "with --graph or --false-loops: the false loops' draw", false, 7, "N", cmd);
  TCLAP::MultiArg<size_t> false_loops("", "false-loops", "instead: robust back ends against this many false "
                                      "loops (repeatable)", false, "N", cmd);
  TCLAP::ValueArg<size_t> nodes("", "nodes", "with --false-loops: nodes of the Manhattan-like grid walk",
                                false, 3500, "N", cmd);
  TCLAP::ValueArg<std::string> config("c", "config", "with --false-loops: the [graph_optimizer] section of the "
                                      "methods (default: the built-in defaults, as config/default.ini)",
                                      false, "", "INI", cmd);
  TCLAP::MultiArg<std::string> only("", "method", "with --false-loops: run only this method (repeatable; "
                                    "least-squares, fixed, gnc, adaptive, tls, ceres-cauchy)", false, "NAME", cmd);
  TCLAP::MultiArg<std::string> graphs("", "graph", "instead of the grid walk: this pose-graph file (repeatable), "
                                      "from its own guess", false, "FILE", cmd);
  TCLAP::MultiArg<double> shares("", "false-share", "with --graph: false loops as this share of the graph's loops "
                                 "(repeatable; 0.1: one in ten)", false, "S", cmd);
  if (const auto code = swslam::cli::parse(cmd, argc, argv)) return *code;
  try
  {
    if (repeats.getValue() < 1) throw std::invalid_argument("--repeats must be >= 1");
    if (graphs.isSet())
    {
      const swslam::graph::GraphOptimizerParams params =
          config.isSet() ? swslam::app::loadConfig(config.getValue()).system.graph_optimizer
                         : swslam::graph::GraphOptimizerParams();
      auto methods = swslam::bench::ourRobustMethods(params);
#ifdef SWSLAM_WITH_CERES
      methods.push_back({"ceres-cauchy", [params](const swslam::graph::PoseGraph& g, std::vector<size_t>& off) {
                           auto run = runCeresWithLoss(g, 1, CeresCauchy{params});
                           off = swslam::bench::switchedOffEdges(run.result, params);
                           return run;
                         }});
#endif
      if (only.isSet()) methods = swslam::bench::selectMethods(methods, only.getValue());
      for (const std::string& file : graphs.getValue())
      {
        const swslam::graph::PoseGraph g = swslam::graph::loadGraph(file);
        std::vector<size_t> counts;
        for (const double share : shares.isSet() ? shares.getValue() : std::vector<double>{0, 0.1, 0.5, 1.0})
        {
          if (!(share >= 0 && share <= 10)) throw std::invalid_argument("--false-share must be in [0, 10]");
          counts.push_back(static_cast<size_t>(std::lround(share * swslam::graph::loopEdgeCount(g))));
        }
        const std::string name = file.substr(file.find_last_of('/') + 1);
        swslam::bench::falseLoopCases(name, g, counts, params, methods, stdout, seed.getValue());
      }
      return 0;
    }
    if (false_loops.isSet())
    {
      swslam::graph::SyntheticGraphOptions o;
      o.nodes = nodes.getValue();
      o.total_edges = o.nodes * 1558 / 1000;  // the edges per node of the Manhattan M3500 graph
      o.dense_neighbours = 0;
      o.grid_half_extent = std::max(5, static_cast<int>(std::sqrt(o.nodes) / 4));
      const auto s = swslam::graph::makeGridWalkGraph(o);
      const swslam::graph::GraphOptimizerParams params =
          config.isSet() ? swslam::app::loadConfig(config.getValue()).system.graph_optimizer
                         : swslam::graph::GraphOptimizerParams();
      auto methods = swslam::bench::ourRobustMethods(params);
#ifdef SWSLAM_WITH_CERES
      methods.push_back({"ceres-cauchy", [params](const swslam::graph::PoseGraph& g, std::vector<size_t>& off) {
                           auto run = runCeresWithLoss(g, 1, CeresCauchy{params});
                           off = swslam::bench::switchedOffEdges(run.result, params);
                           return run;
                         }});
#endif
      if (only.isSet()) methods = swslam::bench::selectMethods(methods, only.getValue());
      swslam::bench::falseLoopCases("grid-" + std::to_string(o.nodes), s.graph, false_loops.getValue(), params, methods,
                                    stdout, seed.getValue());
      // A public graph too: MRPT's circle of 50 nodes, from its own initial guess.
      const std::string circle = datasets.getValue() + "/graph_2d_circle_50nodes.graph";
      if (std::ifstream(circle).good())
        swslam::bench::falseLoopCases("mrpt-circle-50", swslam::graph::loadGraph(circle), false_loops.getValue(),
                                      params, methods, stdout, seed.getValue());
      else
        std::printf("(MRPT's %s not found: --mrpt-datasets)\n", circle.c_str());
      return 0;
    }
#ifdef SWSLAM_WITH_CERES
    swslam::bench::runGraphBenchmark(datasets.getValue(), repeats.getValue(), runCeres);
#else
    swslam::bench::runGraphBenchmark(datasets.getValue(), repeats.getValue(), {});
#endif
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "swslam-bench-graph: %s\n", e.what());
    return 1;
  }
  return 0;
}

#include <swslam/bench/graph.h>

#include <swslam/graph/io.h>
#include <swslam/graph/sliding_window.h>
#include <swslam/graph/synthetic.h>

#include <mrpt/system/CTicTac.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace swslam::bench
{
BenchGraph gridGraph(size_t nodes, size_t edges, size_t dense, int extent, double wrong, unsigned seed)
{
  graph::SyntheticGraphOptions o;
  o.nodes = nodes, o.total_edges = edges, o.wrong_loop_fraction = wrong, o.seed = seed;
  o.dense_neighbours = dense, o.grid_half_extent = extent;
  auto s = graph::makeGridWalkGraph(o);
  const std::string name = "grid-" + std::to_string(nodes) + "n-" +
                           std::to_string(s.graph.edgeCount()) + "e-" +
                           std::to_string(s.good_loops) + "loops-" +
                           std::to_string(2 * extent + 1) + "m";
  return {name, std::move(s.graph), s.truth};
}

namespace
{
/** Area growing with the node count, so that node density and loop density stay alike. */
int extentFor(size_t nodes) { return std::max(5, static_cast<int>(std::sqrt(nodes) / 2)); }

void printRun(const BenchGraph& g, const SolverRun& r)
{
  std::printf("  %-13s %9.2f ms (cpu %9.2f ms) %4zu it  chi2 %-14.8g", r.solver.c_str(),
              1e3 * r.time_s, 1e3 * r.cpu_s, r.iterations, chi2Of(r.result));
  if (!g.truth.empty())
  {
    const auto e = graph::compareToTruth(r.result, g.truth);
    std::printf(" rmse_xy %.4f m  max_xy %.4f m", e.rmse_xy, e.max_xy);
  }
  std::printf("\n");
}

/** Median and max time of `updates` window optimizations of the newest `window` nodes,
 * each after jittering the window's poses (so every update has work to do). */
double windowCost(size_t nodes, size_t window, int updates)
{
  BenchGraph g = gridGraph(nodes, 3 * nodes, 2, extentFor(nodes), 0, 7);
  graph::GraphOptimizerParams params;
  params.window_size = window;
  std::mt19937 rng(3);
  std::normal_distribution<double> n01;
  std::vector<double> t;
  size_t iters = 0;
  for (int u = 0; u < updates; ++u)
  {
    for (const auto id : g.graph.newestNodes(window))
    {
      const auto& p = g.graph.pose(id);
      g.graph.setPose(id, mrpt::poses::CPose2D(p.x() + 0.05 * n01(rng), p.y() + 0.05 * n01(rng),
                                               p.phi() + 0.01 * n01(rng)));
    }
    mrpt::system::CTicTac timer;
    iters += graph::optimizeWindow(g.graph, params).iterations;
    t.push_back(timer.Tac());
  }
  std::sort(t.begin(), t.end());
  std::printf("  window %zu of %6zu nodes (%6zu edges): median %.3f ms, max %.3f ms, %.1f it\n",
              window, nodes, g.graph.edgeCount(), 1e3 * t[t.size() / 2], 1e3 * t.back(),
              double(iters) / updates);
  return t[t.size() / 2];
}
/** Full optimization of every graph by ours (L2), MRPT and Ceres (`run_ceres`): time, chi2, error. */
void fullOptimizationTable(const std::vector<BenchGraph>& graphs, int repeats, const GraphSolver& run_ceres)
{
  graph::GraphOptimizerParams l2;
  l2.kernel_alpha = 2;
  std::printf("== Full optimization, alpha = 2 (median of %d runs, 1 thread)\n", repeats);
  bool all_chi2 = true, all_faster = true, all_faster_cpu = true;
  double paper_sized_ms = 0, paper_sized_cpu_ms = 0;
  for (const auto& g : graphs)
  {
    std::printf("%s: initial chi2 %.8g\n", g.name.c_str(), chi2Of(g.graph));
    const SolverRun ours = runOurs(g.graph, l2, repeats);
    const SolverRun mrpt = runMrpt(g.graph, repeats);
    printRun(g, ours);
    printRun(g, mrpt);
    if (!run_ceres) continue;
    const SolverRun ceres = run_ceres(g.graph, repeats);
    printRun(g, ceres);
    const bool chi2_ok = chi2Of(ours.result) <= 1.001 * chi2Of(ceres.result);
    const bool faster = ours.time_s < ceres.time_s;
    const bool faster_cpu = ours.cpu_s < ceres.cpu_s;
    all_chi2 &= chi2_ok, all_faster &= faster, all_faster_cpu &= faster_cpu;
    if (g.graph.nodeCount() == 638 && paper_sized_ms == 0)
      paper_sized_ms = 1e3 * ours.time_s, paper_sized_cpu_ms = 1e3 * ours.cpu_s;
    std::printf("  chi2 <= ceres + 0.1%%: %s; faster than ceres: wall %s (%.1fx), cpu %s (%.1fx)\n",
                chi2_ok ? "yes" : "NO", faster ? "yes" : "NO", ceres.time_s / ours.time_s,
                faster_cpu ? "yes" : "NO", ceres.cpu_s / ours.cpu_s);
  }
  if (!run_ceres)
  {
    std::printf("ceres: not built (scripts/install-deps.sh --with-bench)\n");
    return;
  }
  std::printf("all graphs: chi2 <= ceres + 0.1%%: %s; faster than ceres: wall %s, cpu %s\n",
              all_chi2 ? "yes" : "NO", all_faster ? "yes" : "NO", all_faster_cpu ? "yes" : "NO");
  std::printf("paper-shaped 638-node / 1952-edge graph: %.2f ms, cpu %.2f ms (target <= 20 ms: %s)\n",
              paper_sized_ms, paper_sized_cpu_ms, paper_sized_ms <= 20 ? "yes" : "NO");
}

/** The window's update cost as the graph grows. */
void windowCostTable()
{
  std::printf("\n== Sliding-window update cost vs graph size (alpha = 0, c = 3)\n");
  std::vector<double> medians;
  for (size_t n : {100, 1000, 10000}) medians.push_back(windowCost(n, 30, 200));
  const double worst = *std::max_element(medians.begin(), medians.end());
  std::printf("window of 30: worst median %.3f ms (target <= 1 ms: %s); 10000 / 100 nodes: %.2fx\n",
              1e3 * worst, worst <= 1e-3 ? "yes" : "NO", medians.back() / medians.front());
}

/** Error against the truth after full optimization, with wrong loops, by kernel shape. */
void wrongLoopsTable()
{
  std::printf("\n== Wrong loops: error vs truth after full optimization (grid 638n, 17 m)\n");
  for (double wrong : {0.1, 0.2, 0.3})
  {
    BenchGraph g = gridGraph(638, 1952, 1, 8, wrong, 11);
    for (double alpha : {2.0, 0.0, -2.0})
    {
      graph::GraphOptimizerParams p;
      p.kernel_alpha = alpha;
      const SolverRun r = runOurs(g.graph, p, 1);
      const auto e = graph::compareToTruth(r.result, g.truth);
      std::printf("  %2.0f%% wrong, alpha %4.1f: rmse_xy %8.4f m  max_xy %8.4f m  (%.2f ms)\n",
                  100 * wrong, alpha, e.rmse_xy, e.max_xy, 1e3 * r.time_s);
    }
  }
}
}  // namespace

void runGraphBenchmark(const std::string& mrpt_datasets, int repeats, const GraphSolver& run_ceres)
{
  std::vector<BenchGraph> graphs;
  const std::string circle = mrpt_datasets + "/graph_2d_circle_50nodes";
  graphs.push_back({"mrpt-circle-50", graph::loadGraph(circle + ".graph"),
                    graph::truthFromGraph(graph::loadGraph(circle + "_groundtruth.graph"))});
  // The paper's Table I size, shaped like its graph: each node linked to its 3 predecessors
  // (consecutive + dense neighbours), the rest loops; then a loop-heavy graph of the same
  // size (a small area revisited over and over), and larger ones.
  graphs.push_back(gridGraph(638, 1952, 2, 12, 0, 1));
  graphs.push_back(gridGraph(638, 1952, 1, 5, 0, 1));
  graphs.push_back(gridGraph(2000, 6000, 2, extentFor(2000), 0, 2));
  graphs.push_back(gridGraph(10000, 30000, 2, extentFor(10000), 0, 3));
  fullOptimizationTable(graphs, repeats, run_ceres);
  windowCostTable();
  wrongLoopsTable();
}

}  // namespace swslam::bench

#include <swslam/bench/graph_solvers.h>

#include <swslam/graph/optimizer.h>
#include <swslam/graph/sliding_window.h>

#include <mrpt/graphslam/levmarq.h>
#include <mrpt/system/CTicTac.h>

#include <algorithm>
#include <ctime>
#include <vector>

namespace swslam::bench
{
namespace
{
double processCpuSeconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}
}  // namespace

void timeSolver(int repeats, const std::function<void()>& run, SolverRun& out)
{
  std::vector<double> wall, cpu;
  for (int k = 0; k < repeats; ++k)
  {
    mrpt::system::CTicTac timer;
    const double cpu0 = processCpuSeconds();
    run();
    wall.push_back(timer.Tac());
    cpu.push_back(processCpuSeconds() - cpu0);
  }
  std::sort(wall.begin(), wall.end());
  std::sort(cpu.begin(), cpu.end());
  out.time_s = wall[wall.size() / 2];
  out.cpu_s = cpu[cpu.size() / 2];
}

double chi2Of(const graph::PoseGraph& graph) { return graph::graphChi2(graph::fullSubproblem(graph, {}).problem); }

SolverRun runOurs(const graph::PoseGraph& graph, const graph::GraphOptimizerParams& params, int repeats)
{
  SolverRun run{"swslam", 0, 0, 0, graph};
  timeSolver(repeats, [&] {
    run.result = graph;
    run.iterations = graph::optimizeFull(run.result, params).iterations;
  }, run);
  return run;
}

SolverRun runMrpt(const graph::PoseGraph& graph, int repeats)
{
  SolverRun run{"mrpt-levmarq", 0, 0, 0, graph};
  mrpt::graphs::CNetworkOfPoses2DInf net;
  timeSolver(repeats, [&] {
    net = graph.network();
    mrpt::graphslam::TResultInfoSpaLevMarq info;
    mrpt::graphslam::optimize_graph_spa_levmarq(net, info);
    run.iterations = info.num_iters;
  }, run);
  for (const auto& [id, pose] : net.nodes) run.result.setPose(id, pose);
  return run;
}

}  // namespace swslam::bench

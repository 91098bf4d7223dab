#include "bench_graph_solvers.h"

#include <swslam/graph/sliding_window.h>

#include <ceres/ceres.h>
#include <mrpt/graphslam/levmarq.h>
#include <mrpt/system/CTicTac.h>

#include <Eigen/Dense>

#include <algorithm>
#include <ctime>
#include <functional>
#include <unordered_map>
#include <vector>

namespace
{
double processCpuSeconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/** Median wall and CPU time of `repeats` calls of `run`, stored in `out`. */
void timeRuns(int repeats, const std::function<void()>& run, SolverRun& out)
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

/** Same residual as swslam::se2Error, times the square root of the information. */
struct RelativePoseCost
{
  RelativePoseCost(const swslam::geometry::Pose2& z, const Eigen::Matrix3d& info)
      : z_(z), sqrt_info_(Eigen::LLT<Eigen::Matrix3d>(info).matrixL().transpose())
  {
  }
  template <typename T>
  bool operator()(const T* pi, const T* pj, T* residual) const
  {
    using std::cos, std::sin, std::floor;
    const T ci = cos(pi[2]), si = sin(pi[2]);
    const T d0 = ci * (pj[0] - pi[0]) + si * (pj[1] - pi[1]) - z_.x();
    const T d1 = -si * (pj[0] - pi[0]) + ci * (pj[1] - pi[1]) - z_.y();
    const double cz = std::cos(z_.z()), sz = std::sin(z_.z());
    T a = pj[2] - pi[2] - z_.z();
    a -= T(2 * M_PI) * floor((a + T(M_PI)) / T(2 * M_PI));
    const T e[3] = {cz * d0 + sz * d1, -sz * d0 + cz * d1, a};
    for (int r = 0; r < 3; ++r)
      residual[r] = sqrt_info_(r, 0) * e[0] + sqrt_info_(r, 1) * e[1] + sqrt_info_(r, 2) * e[2];
    return true;
  }
  swslam::geometry::Pose2 z_;
  Eigen::Matrix3d sqrt_info_;
};
}  // namespace

double chi2Of(const swslam::graph::PoseGraph& graph)
{
  return swslam::graph::graphChi2(swslam::graph::fullSubproblem(graph, {}).problem);
}

SolverRun runOurs(const swslam::graph::PoseGraph& graph, const swslam::graph::GraphOptimizerParams& params,
                  int repeats)
{
  SolverRun run{"swslam", 0, 0, 0, graph};
  timeRuns(repeats, [&] {
    run.result = graph;
    run.iterations = swslam::graph::optimizeFull(run.result, params).iterations;
  }, run);
  return run;
}

SolverRun runMrpt(const swslam::graph::PoseGraph& graph, int repeats)
{
  SolverRun run{"mrpt-levmarq", 0, 0, 0, graph};
  mrpt::graphs::CNetworkOfPoses2DInf net;
  timeRuns(repeats, [&] {
    net = graph.network();
    mrpt::graphslam::TResultInfoSpaLevMarq info;
    mrpt::graphslam::optimize_graph_spa_levmarq(net, info);
    run.iterations = info.num_iters;
  }, run);
  for (const auto& [id, pose] : net.nodes) run.result.setPose(id, pose);
  return run;
}

SolverRun runCeres(const swslam::graph::PoseGraph& graph, int repeats)
{
  SolverRun run{"ceres", 0, 0, 0, graph};
  const std::vector<swslam::graph::PoseGraph::TNodeID> ids = graph.nodeIds();
  std::vector<double> x;
  timeRuns(repeats, [&] {
    x.clear();
    std::unordered_map<swslam::graph::PoseGraph::TNodeID, size_t> index;
    for (const auto id : ids)
    {
      const auto& p = graph.pose(id);
      index[id] = x.size();
      x.insert(x.end(), {p.x(), p.y(), p.phi()});
    }
    ceres::Problem problem;
    for (size_t k = 0; k < graph.edgeCount(); ++k)
    {
      const auto& e = graph.edge(k);
      const auto& m = e.measurement->mean;
      const size_t i = index[e.from], j = index[e.to];
      auto* cost = new ceres::AutoDiffCostFunction<RelativePoseCost, 3, 3, 3>(
          new RelativePoseCost(swslam::geometry::Pose2(m.x(), m.y(), m.phi()),
                               e.measurement->cov_inv.asEigen()));
      problem.AddResidualBlock(cost, nullptr, &x[i], &x[j]);
    }
    double* root = &x[index[graph.root()]];
    if (problem.HasParameterBlock(root)) problem.SetParameterBlockConstant(root);
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    options.max_num_iterations = 100;
    options.num_threads = 1;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    run.iterations = summary.iterations.size();
  }, run);
  for (size_t k = 0; k < ids.size(); ++k)
    run.result.setPose(ids[k], mrpt::poses::CPose2D(x[3 * k], x[3 * k + 1], x[3 * k + 2]));
  return run;
}

#include "ceres_solver.h"

#include <swslam/graph/sliding_window.h>

#include <ceres/ceres.h>

#include <Eigen/Dense>

#include <cmath>
#include <functional>
#include <unordered_map>
#include <vector>

namespace
{
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

swslam::bench::SolverRun runCeres(const swslam::graph::PoseGraph& graph, int repeats)
{
  return runCeresWithLoss(graph, repeats, {});
}

swslam::bench::SolverRun runCeresWithLoss(const swslam::graph::PoseGraph& graph, int repeats,
                                          const std::optional<CeresCauchy>& cauchy)
{
  swslam::bench::SolverRun run{cauchy ? "ceres-cauchy" : "ceres", 0, 0, 0, graph};
  const std::vector<swslam::graph::PoseGraph::TNodeID> ids = graph.nodeIds();
  std::vector<double> x;
  swslam::bench::timeSolver(repeats, [&] {
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
      // Ceres' Cauchy loss a^2 log(1 + s / a^2) on s = r^2 is our normalized Cauchy kernel
      // (alpha 0) of scale c when a = c sqrt(2).
      ceres::LossFunction* loss = cauchy && cauchy->robust.isRobust(e.kind)
                                      ? new ceres::CauchyLoss(std::sqrt(2.0) * cauchy->robust.kernel_c)
                                      : nullptr;
      problem.AddResidualBlock(cost, loss, &x[i], &x[j]);
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

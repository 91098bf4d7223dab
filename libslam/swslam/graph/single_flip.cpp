#include <swslam/graph/single_flip.h>

#include <swslam/geometry/se2_error.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <numeric>
#include <stdexcept>

namespace swslam::graph
{
namespace
{
/** Union-find root of p. */
int root(std::vector<int>& parent, int p)
{
  while (parent[p] != p) p = parent[p] = parent[parent[p]];
  return p;
}
}  // namespace

std::vector<double> singleFlipChanges(const GraphProblem& problem, const std::vector<char>& kept,
                                      const std::vector<size_t>& candidates, const OutlierGates& gates)
{
  const int n = static_cast<int>(problem.poses.size());
  auto in = [&](size_t k) { return !problem.edges[k].robust || kept[k]; };
  // The components of the kept edges; each is held at a fixed pose or else at its first pose.
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (size_t k = 0; k < problem.edges.size(); ++k)
    if (in(k)) parent[root(parent, problem.edges[k].i)] = root(parent, problem.edges[k].j);
  std::vector<char> held(n, 0), component_held(n, 0);
  for (int p = 0; p < n; ++p)
    if (!problem.fixed.empty() && problem.fixed[p]) held[p] = component_held[root(parent, p)] = 1;
  for (int p = 0; p < n; ++p)
    if (!component_held[root(parent, p)]) held[p] = component_held[root(parent, p)] = 1;
  std::vector<int> column(n, -1);
  int free = 0;
  for (int p = 0; p < n; ++p)
    if (!held[p]) column[p] = 3 * free++;

  // H = sum over the kept edges of J^T Omega J, in the free poses.
  std::vector<Eigen::Triplet<double>> triplets;
  auto add = [&](int a, int b, const Eigen::Matrix3d& block) {
    if (column[a] < 0 || column[b] < 0) return;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) triplets.emplace_back(column[a] + r, column[b] + c, block(r, c));
  };
  for (size_t k = 0; k < problem.edges.size(); ++k)
  {
    if (!in(k)) continue;
    const auto& e = problem.edges[k];
    Eigen::Matrix3d A, B;
    geometry::se2ErrorWithJacobians(problem.poses[e.i], problem.poses[e.j], e.z, A, B);
    add(e.i, e.i, A.transpose() * e.information * A);
    add(e.i, e.j, A.transpose() * e.information * B);
    add(e.j, e.i, B.transpose() * e.information * A);
    add(e.j, e.j, B.transpose() * e.information * B);
  }
  Eigen::SparseMatrix<double> H(3 * free, 3 * free);
  H.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor;
  if (free > 0)
  {
    factor.compute(H);
    if (factor.info() != Eigen::Success) throw std::runtime_error("single flip: the normal matrix cannot be factored");
  }

  std::vector<double> out;
  out.reserve(candidates.size());
  for (const size_t k : candidates)
  {
    const auto& e = problem.edges[k];
    const double gate2 = gates.of(e) * gates.of(e);
    Eigen::Matrix3d A, B;
    const Eigen::Vector3d err = geometry::se2ErrorWithJacobians(problem.poses[e.i], problem.poses[e.j], e.z, A, B);
    const Eigen::Matrix3d S = e.information.inverse();
    if (root(parent, e.i) != root(parent, e.j))
    {
      out.push_back(kept[k] ? gate2 : -gate2);  // nothing else ties its ends
      continue;
    }
    // P = J H^-1 J^T, the covariance of the edge's error predicted by the kept edges.
    Eigen::MatrixXd Jt = Eigen::MatrixXd::Zero(3 * free, 3);
    if (column[e.i] >= 0) Jt.middleRows<3>(column[e.i]) += A.transpose();
    if (column[e.j] >= 0) Jt.middleRows<3>(column[e.j]) += B.transpose();
    Eigen::Matrix3d P = Eigen::Matrix3d::Zero();
    if (free > 0)
    {
      const Eigen::MatrixXd X = factor.solve(Jt);
      P = Jt.transpose() * X;
    }
    if (kept[k])
    {
      // Removing it: the residual's covariance S - P is singular where it alone ties its ends
      // (then it is fitted exactly and its removal lowers nothing).
      const Eigen::Matrix3d R = 0.5 * (S - P + (S - P).transpose());
      const Eigen::LDLT<Eigen::Matrix3d> ldlt(R);
      const double scale = S.diagonal().maxCoeff();
      const bool singular = ldlt.info() != Eigen::Success || ldlt.vectorD().minCoeff() <= 1e-9 * scale;
      out.push_back(singular ? gate2 : gate2 - err.dot(ldlt.solve(err)));
    }
    else
      out.push_back(err.dot((S + P).ldlt().solve(err)) - gate2);
  }
  return out;
}

}  // namespace swslam::graph

#include <swslam/graph/single_flip.h>

#include <swslam/geometry/se2_error.h>
#include <swslam/graph/levenberg_marquardt.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <stdexcept>

namespace swslam::graph
{
namespace
{
/** The kept edges' normal matrix H = sum J^T Omega J at the problem's poses, factored, with
 * each pose's first column in it (-1: held) and its connected component. */
struct KeptSystem
{
  std::vector<int> column, roots;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor;
  int size = 0;
};

void buildKeptSystem(const GraphProblem& problem, const std::vector<char>& kept, KeptSystem& sys)
{
  GraphProblem in = problem;
  in.edges.clear();
  for (size_t k = 0; k < problem.edges.size(); ++k)
    if (!problem.edges[k].robust || kept[k]) in.edges.push_back(problem.edges[k]);
  in.fixed.resize(in.poses.size(), 0);
  size_t components = 0;
  sys.column = variableIndex(in, components);
  for (int& c : sys.column) c = c < 0 ? -1 : 3 * c;
  sys.roots = componentRoots(in);
  int free = 0;
  for (const int c : sys.column) free += c >= 0;
  sys.size = 3 * free;

  std::vector<Eigen::Triplet<double>> triplets;
  auto add = [&](int a, int b, const Eigen::Matrix3d& block) {
    if (sys.column[a] < 0 || sys.column[b] < 0) return;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) triplets.emplace_back(sys.column[a] + r, sys.column[b] + c, block(r, c));
  };
  for (const auto& e : in.edges)
  {
    Eigen::Matrix3d A, B;
    geometry::se2ErrorWithJacobians(in.poses[e.i], in.poses[e.j], e.z, A, B);
    add(e.i, e.i, A.transpose() * e.information * A);
    add(e.i, e.j, A.transpose() * e.information * B);
    add(e.j, e.i, B.transpose() * e.information * A);
    add(e.j, e.j, B.transpose() * e.information * B);
  }
  if (sys.size == 0) return;
  Eigen::SparseMatrix<double> H(sys.size, sys.size);
  H.setFromTriplets(triplets.begin(), triplets.end());
  sys.factor.compute(H);
  if (sys.factor.info() != Eigen::Success) throw std::runtime_error("single flip: the normal matrix cannot be factored");
}

/** P = J H^-1 J^T: the covariance of edge e's error that the kept edges predict. */
Eigen::Matrix3d predictedCovariance(const KeptSystem& sys, const GraphProblem::Edge& e, const Eigen::Matrix3d& A,
                                    const Eigen::Matrix3d& B)
{
  if (sys.size == 0) return Eigen::Matrix3d::Zero();
  Eigen::MatrixXd Jt = Eigen::MatrixXd::Zero(sys.size, 3);
  if (sys.column[e.i] >= 0) Jt.middleRows<3>(sys.column[e.i]) += A.transpose();
  if (sys.column[e.j] >= 0) Jt.middleRows<3>(sys.column[e.j]) += B.transpose();
  return Jt.transpose() * sys.factor.solve(Jt);
}
}  // namespace

std::vector<double> singleFlipChanges(const GraphProblem& problem, const std::vector<char>& kept,
                                      const std::vector<size_t>& candidates, const OutlierGates& gates)
{
  KeptSystem sys;
  buildKeptSystem(problem, kept, sys);
  std::vector<double> out;
  out.reserve(candidates.size());
  for (const size_t k : candidates)
  {
    const auto& e = problem.edges[k];
    const double gate2 = gates.of(e) * gates.of(e);
    if (sys.roots[e.i] != sys.roots[e.j])
    {
      out.push_back(kept[k] ? gate2 : -gate2);  // nothing else ties its ends
      continue;
    }
    Eigen::Matrix3d A, B;
    const Eigen::Vector3d err = geometry::se2ErrorWithJacobians(problem.poses[e.i], problem.poses[e.j], e.z, A, B);
    const Eigen::Matrix3d S = e.information.inverse();
    const Eigen::Matrix3d P = predictedCovariance(sys, e, A, B);
    if (!kept[k])
    {
      out.push_back(err.dot((S + P).ldlt().solve(err)) - gate2);
      continue;
    }
    // Removing it: the residual's covariance S - P is singular where it alone ties its ends
    // (then it is fitted exactly and its removal lowers nothing).
    const Eigen::Matrix3d R = 0.5 * (S - P + (S - P).transpose());
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(R);
    const bool singular =
        ldlt.info() != Eigen::Success || ldlt.vectorD().minCoeff() <= 1e-9 * S.diagonal().maxCoeff();
    out.push_back(singular ? gate2 : gate2 - err.dot(ldlt.solve(err)));
  }
  return out;
}

}  // namespace swslam::graph

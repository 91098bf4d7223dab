#include <swslam/graph/initialization.h>

#include <swslam/graph/truncated.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <mrpt/system/CTicTac.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>

namespace swslam::graph
{
namespace
{
/** Per pose, the edges that touch it. */
std::vector<std::vector<int>> incidence(const GraphProblem& problem)
{
  std::vector<std::vector<int>> at(problem.poses.size());
  for (size_t k = 0; k < problem.edges.size(); ++k)
  {
    at[problem.edges[k].i].push_back(static_cast<int>(k));
    at[problem.edges[k].j].push_back(static_cast<int>(k));
  }
  return at;
}

/** The anchors: fixed poses, and the poses the spanning tree starts a component from (-1 in
 * `tree` and not reached from a fixed pose). */
std::vector<char> anchors(const GraphProblem& problem, const std::vector<int>& tree)
{
  std::vector<char> anchor(problem.poses.size(), 0);
  for (size_t p = 0; p < problem.poses.size(); ++p) anchor[p] = tree[p] < 0 || problem.fixed[p];
  return anchor;
}

/** Solves the linear least squares of `dims` unknowns per free pose, A x = b (A symmetric
 * positive definite, assembled as triplets of free-pose blocks); x per pose, anchors 0. */
Eigen::VectorXd solveFree(const std::vector<Eigen::Triplet<double>>& triplets, const Eigen::VectorXd& b, int size)
{
  Eigen::SparseMatrix<double> A(size, size);
  A.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
  if (ldlt.info() != Eigen::Success) throw std::runtime_error("lagoPoses: the linear system is singular");
  Eigen::VectorXd x = ldlt.solve(b);
  if (ldlt.info() != Eigen::Success || !x.allFinite())
    throw std::runtime_error("lagoPoses: the linear system could not be solved");
  return x;
}

Eigen::Matrix2d rotation(double theta)
{
  const double c = std::cos(theta), s = std::sin(theta);
  return (Eigen::Matrix2d() << c, -s, s, c).finished();
}
}  // namespace

std::vector<int> spanningTree(const GraphProblem& problem)
{
  checkProblem(problem);
  const size_t n = problem.poses.size();
  const auto at = incidence(problem);
  // Dijkstra on the heading's variance: each pose reached by the path along which its heading
  // is known best, so that the multiples of 2 pi read off the tree are the likeliest (a path
  // along a long odometry chain can drift by more than pi where a loop is certain).
  std::vector<int> tree(n, -1);
  std::vector<double> cost(n, std::numeric_limits<double>::infinity());
  std::vector<char> done(n, 0);
  using Item = std::pair<double, size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  auto grow = [&]() {
    while (!heap.empty())
    {
      const auto [reached, p] = heap.top();
      heap.pop();
      if (done[p]) continue;
      done[p] = 1;
      for (const int k : at[p])
      {
        const auto& e = problem.edges[k];
        const size_t q = static_cast<size_t>(e.i) == p ? e.j : e.i;
        const double c = reached + e.information.inverse()(2, 2);
        if (done[q] || cost[q] <= c) continue;
        cost[q] = c;
        tree[q] = k;
        heap.push({c, q});
      }
    }
  };
  for (size_t p = 0; p < n; ++p)
    if (problem.fixed[p]) cost[p] = 0, heap.push({0.0, p});
  grow();
  for (size_t p = 0; p < n; ++p)
    if (!done[p])
    {
      cost[p] = 0;  // a component without a fixed pose starts at its first pose
      heap.push({0.0, p});
      grow();
    }
  return tree;
}

std::vector<double> unwrappedRotations(const GraphProblem& problem, const std::vector<int>& tree)
{
  const size_t n = problem.poses.size();
  // The tree's headings, composed outwards from the anchors (the tree's order of discovery is
  // not kept, so pass over it until every heading is known: at most its depth).
  std::vector<double> heading(n, 0);
  std::vector<char> known(n, 0);
  for (size_t p = 0; p < n; ++p)
    if (tree[p] < 0) heading[p] = problem.poses[p].z(), known[p] = 1;
  for (bool changed = true; changed;)
  {
    changed = false;
    for (size_t p = 0; p < n; ++p)
    {
      if (known[p]) continue;
      const auto& e = problem.edges[tree[p]];
      const size_t from = static_cast<size_t>(e.i) == p ? e.j : e.i;
      if (!known[from]) continue;
      heading[p] = static_cast<size_t>(e.j) == p ? heading[from] + e.z.z() : heading[from] - e.z.z();
      known[p] = 1;
      changed = true;
    }
  }
  std::vector<double> d(problem.edges.size());
  for (size_t k = 0; k < problem.edges.size(); ++k)
  {
    const auto& e = problem.edges[k];
    const double turns = std::round((heading[e.j] - heading[e.i] - e.z.z()) / (2 * M_PI));
    d[k] = e.z.z() + 2 * M_PI * turns;
  }
  return d;
}

namespace
{
/** The unknowns of the free poses: per pose, its index, -1 for an anchor. */
std::vector<int> freeIndex(const GraphProblem& problem, const std::vector<int>& tree, int& free)
{
  const std::vector<char> anchor = anchors(problem, tree);
  std::vector<int> index(problem.poses.size(), -1);
  free = 0;
  for (size_t p = 0; p < problem.poses.size(); ++p)
    if (!anchor[p]) index[p] = free++;
  return index;
}

/** An edge that is no loop (a step of the chain) switched off still weighs this much in robust
 * LAGO's solves: it holds the poses it alone joins, while weighing nothing against the others. */
constexpr double kChainWeightFloor = 1e-6;

double effectiveWeight(const GraphProblem::Edge& e, double weight)
{
  return e.kind == EdgeKind::Loop ? weight : std::max(weight, kChainWeightFloor);
}

/** The headings that minimize sum w_k (theta_j - theta_i - d_k)^2 / var_k over the edges of
 * positive weight, written into `poses` (the anchors' kept). */
void solveHeadings(const GraphProblem& problem, const std::vector<double>& d, const std::vector<int>& index, int free,
                   const std::vector<double>& weight, std::vector<geometry::Pose2>& poses)
{
  std::vector<Eigen::Triplet<double>> a;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(free);
  for (size_t k = 0; k < problem.edges.size(); ++k)
  {
    const auto& e = problem.edges[k];
    const double wk = effectiveWeight(e, weight[k]);
    if (wk <= 0) continue;
    const double w = wk / e.information.inverse()(2, 2);
    const int i = index[e.i], j = index[e.j];
    if (i >= 0) a.emplace_back(i, i, w), b(i) -= w * d[k];
    if (j >= 0) a.emplace_back(j, j, w), b(j) += w * d[k];
    if (i >= 0 && j >= 0) a.emplace_back(i, j, -w), a.emplace_back(j, i, -w);
    if (i >= 0 && j < 0) b(i) += w * poses[e.j].z();
    if (j >= 0 && i < 0) b(j) += w * poses[e.i].z();
  }
  const Eigen::VectorXd theta = solveFree(a, b, free);
  for (size_t p = 0; p < poses.size(); ++p)
    if (index[p] >= 0) poses[p].z() = theta(index[p]);
}

/** Edge k's translation residual t_j - t_i - R(theta_i) z and its information turned by theta_i. */
void translationTerm(const GraphProblem::Edge& e, const std::vector<geometry::Pose2>& poses, Eigen::Vector2d& r,
                     Eigen::Matrix2d& W, Eigen::Vector2d& c)
{
  const Eigen::Matrix2d R = rotation(poses[e.i].z());
  W = R * e.information.inverse().topLeftCorner<2, 2>().inverse() * R.transpose();
  c = R * e.z.head<2>();
  r = poses[e.j].head<2>() - poses[e.i].head<2>() - c;
}

/** The positions that minimize sum w_k |t_j - t_i - R(theta_i) z_k|^2 under the edges'
 * translation information turned by theta_i, given the headings in `poses`. */
void solvePositions(const GraphProblem& problem, const std::vector<int>& index, int free,
                    const std::vector<double>& weight, std::vector<geometry::Pose2>& poses)
{
  std::vector<Eigen::Triplet<double>> a;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(2 * free);
  for (size_t k = 0; k < problem.edges.size(); ++k)
  {
    const auto& e = problem.edges[k];
    const double wk = effectiveWeight(e, weight[k]);
    if (wk <= 0) continue;
    Eigen::Vector2d r, c;
    Eigen::Matrix2d W;
    translationTerm(e, poses, r, W, c);
    W *= wk;
    const int i = index[e.i], j = index[e.j];
    auto block = [&](int row, int col, const Eigen::Matrix2d& m) {
      for (int u = 0; u < 2; ++u)
        for (int v = 0; v < 2; ++v) a.emplace_back(2 * row + u, 2 * col + v, m(u, v));
    };
    if (i >= 0) block(i, i, W), b.segment<2>(2 * i) -= W * c;
    if (j >= 0) block(j, j, W), b.segment<2>(2 * j) += W * c;
    if (i >= 0 && j >= 0) block(i, j, -W), block(j, i, -W);
    if (i >= 0 && j < 0) b.segment<2>(2 * i) += W * poses[e.j].head<2>();
    if (j >= 0 && i < 0) b.segment<2>(2 * j) += W * poses[e.i].head<2>();
  }
  const Eigen::VectorXd t = solveFree(a, b, 2 * free);
  for (size_t p = 0; p < poses.size(); ++p)
    if (index[p] >= 0) poses[p].head<2>() = t.segment<2>(2 * index[p]);
}

/** Each edge's rotation unwrapped by the multiple of 2 pi that agrees with the headings of `poses`. */
std::vector<double> unwrappedAt(const GraphProblem& problem, const std::vector<geometry::Pose2>& poses)
{
  std::vector<double> d(problem.edges.size());
  for (size_t k = 0; k < problem.edges.size(); ++k)
  {
    const auto& e = problem.edges[k];
    d[k] = e.z.z() + 2 * M_PI * std::round((poses[e.j].z() - poses[e.i].z() - e.z.z()) / (2 * M_PI));
  }
  return d;
}

/** The chi-square quantiles at 0.999 of one and two degrees of freedom: robust LAGO's gates on
 * a loop's heading and translation residuals (a proposal only: the decision's own gate is
 * outlier_gate). */
constexpr double kHeadingGate2 = 10.83;
constexpr double kTranslationGate2 = 13.82;
/** Robust LAGO unwraps the rotations again at its headings at most this many times. */
constexpr int kMaxUnwraps = 2;
}  // namespace

std::vector<double> lagoHeadings(const GraphProblem& problem)
{
  const std::vector<int> tree = spanningTree(problem);
  int free = 0;
  const std::vector<int> index = freeIndex(problem, tree, free);
  std::vector<geometry::Pose2> poses = problem.poses;
  if (free > 0)
    solveHeadings(problem, unwrappedRotations(problem, tree), index, free, std::vector<double>(problem.edges.size(), 1.0), poses);
  std::vector<double> theta(poses.size());
  for (size_t p = 0; p < poses.size(); ++p) theta[p] = poses[p].z();
  return theta;
}

std::vector<geometry::Pose2> lagoPositions(const GraphProblem& problem, const std::vector<double>& headings)
{
  int free = 0;
  const std::vector<int> index = freeIndex(problem, spanningTree(problem), free);
  std::vector<geometry::Pose2> poses = problem.poses;
  for (size_t p = 0; p < poses.size(); ++p) poses[p].z() = headings[p];
  if (free > 0) solvePositions(problem, index, free, std::vector<double>(problem.edges.size(), 1.0), poses);
  for (auto& p : poses) p.z() = std::remainder(p.z(), 2 * M_PI);
  return poses;
}

std::vector<geometry::Pose2> lagoPoses(const GraphProblem& problem)
{
  return lagoPositions(problem, lagoHeadings(problem));
}

RobustLago robustLagoPoses(const GraphProblem& problem, const std::vector<char>& use, const OutlierGates& gates)
{
  const size_t m = problem.edges.size();
  // The tree along the edges that are no loops where they reach (the odometry chain): a false
  // loop in the tree would unwrap every rotation against its wrong heading.
  GraphProblem trusted = problem;
  for (auto& e : trusted.edges)
    if (e.kind == EdgeKind::Loop) e.information *= 1e-12;
  const std::vector<int> tree = spanningTree(trusted);
  int free = 0;
  const std::vector<int> index = freeIndex(problem, tree, free);
  RobustLago out{problem.poses, std::vector<char>(m, 0)};
  if (free == 0) return out;
  std::vector<char> robust(m);
  // The gates of one and two degrees of freedom, each kind's scaled as its gate of three.
  std::vector<double> heading_c2(m), translation_c2(m);
  for (size_t k = 0; k < m; ++k)
  {
    robust[k] = problem.edges[k].robust;
    const double scale = gates.of(problem.edges[k]) / gates.loop;  // an edge of the chain: wider
    heading_c2[k] = kHeadingGate2 * scale * scale;
    translation_c2[k] = kTranslationGate2 * scale * scale;
  }
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> d = unwrappedRotations(problem, tree);
  std::vector<double> w;
  for (int pass = 0; pass <= kMaxUnwraps; ++pass)
  {
    w = graduatedTls(
        robust, heading_c2, 0, [&](const std::vector<double>& wk) { solveHeadings(problem, d, index, free, wk, out.poses); },
        [&](size_t k) {
          const auto& e = problem.edges[k];
          if (!use[k]) return inf;
          const double r = out.poses[e.j].z() - out.poses[e.i].z() - d[k];
          return r * r / e.information.inverse()(2, 2);
        });
    const std::vector<double> again = unwrappedAt(problem, out.poses);
    if (again == d) break;
    d = again;
  }
  const std::vector<double> headings = w;
  w = graduatedTls(
      robust, translation_c2, 0, [&](const std::vector<double>& wk) { solvePositions(problem, index, free, wk, out.poses); },
      [&](size_t k) {
        if (headings[k] < 0.5) return inf;
        Eigen::Vector2d r, c;
        Eigen::Matrix2d W;
        translationTerm(problem.edges[k], out.poses, r, W, c);
        return r.dot(W * r);
      });
  for (size_t k = 0; k < m; ++k) out.inliers[k] = w[k] >= 0.5;
  for (auto& p : out.poses) p.z() = std::remainder(p.z(), 2 * M_PI);
  return out;
}

OptimizationReport optimizeFromBestStart(GraphProblem& problem, const GraphOptimizerParams& params)
{
  // Tls proposes LAGO's poses itself, among others.
  if (params.kernel_schedule == KernelSchedule::Tls) return optimizeGraphProblem(problem, params);
  const KindKernels kernels = uniformKernels(params.kernel());
  GraphProblem guess = problem;
  OptimizationReport from_guess = optimizeGraphProblem(guess, params);
  mrpt::system::CTicTac lago_timer;
  GraphProblem lago = problem;
  try
  {
    lago.poses = lagoPoses(problem);
  }
  catch (const std::runtime_error&)
  {
    lago.poses.clear();  // a singular system: no LAGO start
  }
  from_guess.time_s += lago_timer.Tac();
  // Where the guess's run ended below LAGO's start, LAGO's run is not tried: a guess that was
  // good (a graph optimized before, as the system's) ends at the optimum LAGO's would reach.
  if (lago.poses.empty() || (from_guess.status != OptimizationStatus::Diverged &&
                             !(robustCost(lago, kernels) < robustCost(guess, kernels))))
  {
    problem.poses = guess.poses;
    return from_guess;
  }
  OptimizationReport from_lago = optimizeGraphProblem(lago, params);
  const bool lago_wins = from_lago.status != OptimizationStatus::Diverged &&
                         (from_guess.status == OptimizationStatus::Diverged || from_lago.final_cost < from_guess.final_cost);
  OptimizationReport& kept = lago_wins ? from_lago : from_guess;
  const OptimizationReport& other = lago_wins ? from_guess : from_lago;
  problem.poses = (lago_wins ? lago : guess).poses;
  kept.lago_start = lago_wins;
  kept.time_s += other.time_s;
  kept.iterations += other.iterations;
  kept.message += lago_wins ? " (from LAGO's start: the guess ended at a higher cost)"
                            : " (from the guess: LAGO's start ended at a higher cost)";
  return kept;
}

}  // namespace swslam::graph

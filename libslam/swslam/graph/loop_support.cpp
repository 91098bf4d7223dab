#include <swslam/graph/loop_support.h>

#include <swslam/graph/node_merge.h>

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPosePDFGaussian.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace swslam::graph
{
namespace
{
using mrpt::poses::CPosePDFGaussian;

/** An edge's measurement as a Gaussian on (x, y, theta) in the frame of its first pose. */
CPosePDFGaussian measured(const GraphProblem::Edge& e)
{
  return measurementGaussian(mrpt::poses::CPose2D(e.z.x(), e.z.y(), e.z.z()), e.information);
}

CPosePDFGaussian inverted(const CPosePDFGaussian& p)
{
  CPosePDFGaussian out;
  p.inverse(out);
  return out;
}

/** Every edge's measurement as a Gaussian, and its inverse: built once, composed many times. */
struct Measurements
{
  explicit Measurements(const GraphProblem& problem)
  {
    forward.reserve(problem.edges.size());
    backward.reserve(problem.edges.size());
    for (const auto& e : problem.edges)
    {
      forward.push_back(measured(e));
      backward.push_back(inverted(forward.back()));
    }
  }
  std::vector<CPosePDFGaussian> forward, backward;
};

/** The chain's relative pose from pose `from` to pose `to` (same chain), composed step by step. */
CPosePDFGaussian alongChain(const GraphProblem& problem, const OdometryChain& chain, const Measurements& z, int from,
                            int to)
{
  CPosePDFGaussian t;  // identity, zero covariance
  int p = from;
  while (p != to)
  {
    const bool forward = chain.position[to] > chain.position[p];
    const int k = forward ? chain.next[p] : chain.previous[p];
    t += forward ? z.forward[k] : z.backward[k];
    p = forward ? problem.edges[k].j : problem.edges[k].i;
  }
  return t;
}

bool near(const OdometryChain& chain, int a, int b, int window)
{
  return chain.chain[a] >= 0 && chain.chain[a] == chain.chain[b] && std::abs(chain.position[a] - chain.position[b]) <= window;
}
}  // namespace

OdometryChain odometryChain(const GraphProblem& problem)
{
  const size_t n = problem.poses.size();
  OdometryChain c;
  c.chain.assign(n, -1);
  c.position.assign(n, 0);
  c.next.assign(n, -1);
  c.previous.assign(n, -1);
  for (size_t k = 0; k < problem.edges.size(); ++k)
  {
    const auto& e = problem.edges[k];
    if (e.kind != EdgeKind::Consecutive || c.next[e.i] >= 0 || c.previous[e.j] >= 0) continue;
    c.next[e.i] = static_cast<int>(k);
    c.previous[e.j] = static_cast<int>(k);
  }
  int chains = 0;
  for (size_t p = 0; p < n; ++p)
  {
    if (c.previous[p] >= 0 || c.next[p] < 0) continue;
    // A chain's start: follow it (a cycle of consecutive edges has no start and stays off).
    int at = static_cast<int>(p), pos = 0;
    while (at >= 0 && c.chain[at] < 0)
    {
      c.chain[at] = chains;
      c.position[at] = pos++;
      at = c.next[at] >= 0 ? problem.edges[c.next[at]].j : -1;
    }
    ++chains;
  }
  return c;
}

bool isLoopCandidate(const GraphProblem& problem, const OdometryChain& chain, size_t k)
{
  const auto& e = problem.edges[k];
  return e.robust && chain.next[e.i] != static_cast<int>(k);
}

namespace
{
double cycleChi2(const GraphProblem& problem, const OdometryChain& chain, const Measurements& z, size_t a, size_t b,
                 const LoopSupportOptions& options)
{
  const auto& ea = problem.edges[a];
  const auto& eb = problem.edges[b];
  // b runs from k to l; take it the way that puts k near a's start.
  bool reversed = false;
  if (!(near(chain, ea.i, eb.i, options.window) && near(chain, ea.j, eb.j, options.window)))
  {
    if (!(near(chain, ea.i, eb.j, options.window) && near(chain, ea.j, eb.i, options.window))) return -1;
    reversed = true;
  }
  const int k = reversed ? eb.j : eb.i, l = reversed ? eb.i : eb.j;
  // i -> k along the chain, k -> l by loop b, l -> j along the chain: loop a's prediction.
  CPosePDFGaussian cycle = alongChain(problem, chain, z, ea.i, k);
  cycle += reversed ? z.backward[b] : z.forward[b];
  cycle += alongChain(problem, chain, z, l, ea.j);
  const CPosePDFGaussian& za = z.forward[a];
  Eigen::Vector3d d(cycle.mean.x() - za.mean.x(), cycle.mean.y() - za.mean.y(),
                    mrpt::math::wrapToPi(cycle.mean.phi() - za.mean.phi()));
  const Eigen::Matrix3d S = cycle.cov.asEigen() + za.cov.asEigen();
  return d.dot(S.ldlt().solve(d));
}
}  // namespace

double cycleChi2(const GraphProblem& problem, const OdometryChain& chain, size_t a, size_t b,
                 const LoopSupportOptions& options)
{
  return cycleChi2(problem, chain, Measurements(problem), a, b, options);
}

namespace
{
int findRoot(std::vector<int>& parent, int a)
{
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}
}  // namespace

LoopAgreement loopAgreement(const GraphProblem& problem, const OdometryChain& chain, const LoopSupportOptions& options)
{
  const size_t m = problem.edges.size();
  LoopAgreement out{std::vector<int>(m, -1), std::vector<int>(m, -1)};
  // Loops ordered by their earlier end's chain and position: the neighbours of one are a
  // stretch of this order.
  std::vector<size_t> loops;
  auto key = [&](size_t k) {
    const auto& e = problem.edges[k];
    const int first = chain.position[e.i] <= chain.position[e.j] || chain.chain[e.i] != chain.chain[e.j] ? e.i : e.j;
    return std::make_pair(chain.chain[first], chain.position[first]);
  };
  for (size_t k = 0; k < m; ++k)
    if (isLoopCandidate(problem, chain, k))
    {
      out.support[k] = 0;
      if (chain.chain[problem.edges[k].i] >= 0 && chain.chain[problem.edges[k].j] >= 0) loops.push_back(k);
    }
  std::sort(loops.begin(), loops.end(), [&](size_t a, size_t b) { return key(a) < key(b); });
  const Measurements z(problem);
  std::vector<int> parent(m);
  for (size_t k = 0; k < m; ++k) parent[k] = static_cast<int>(k);
  for (size_t u = 0; u < loops.size(); ++u)
    for (size_t v = u + 1; v < loops.size(); ++v)
    {
      const auto [cu, pu] = key(loops[u]);
      const auto [cv, pv] = key(loops[v]);
      if (cv != cu || pv > pu + options.window) break;
      const double chi2 = cycleChi2(problem, chain, z, loops[u], loops[v], options);
      if (!(chi2 >= 0 && chi2 < options.gate)) continue;
      ++out.support[loops[u]], ++out.support[loops[v]];
      parent[findRoot(parent, static_cast<int>(loops[u]))] = findRoot(parent, static_cast<int>(loops[v]));
    }
  // Runs numbered from 0 in the order of their first edge.
  std::vector<int> number(m, -1);
  int count = 0;
  for (size_t k = 0; k < m; ++k)
  {
    if (out.support[k] < 0) continue;
    int& n = number[findRoot(parent, static_cast<int>(k))];
    if (n < 0) n = count++;
    out.runs[k] = n;
  }
  return out;
}

}  // namespace swslam::graph

#include <swslam/graph/synthetic.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace swslam::graph
{
namespace
{
std::vector<geometry::Pose2> gridWalk(const SyntheticGraphOptions& o, std::mt19937& rng)
{
  std::vector<geometry::Pose2> truth{geometry::Pose2(0, 0, 0)};
  std::uniform_int_distribution<int> turn(-1, 1);  // right, straight, left
  int x = 0, y = 0, heading = 0;                   // heading in quarter turns
  const int dx[] = {1, 0, -1, 0}, dy[] = {0, 1, 0, -1};
  while (truth.size() < o.nodes)
  {
    int h = (heading + 4 + turn(rng)) % 4;
    for (int tries = 0; tries < 4; ++tries, h = (h + 1) % 4)
      if (std::abs(x + dx[h]) <= o.grid_half_extent && std::abs(y + dy[h]) <= o.grid_half_extent)
        break;
    heading = h, x += dx[h], y += dy[h];
    truth.emplace_back(x, y, geometry::wrapAngle(heading * M_PI / 2));
  }
  return truth;
}

mrpt::poses::CPosePDFGaussianInf noisyMeasurement(const geometry::Pose2& rel, const SyntheticGraphOptions& o,
                                                  std::mt19937& rng)
{
  std::normal_distribution<double> n01;
  mrpt::poses::CPosePDFGaussianInf z;
  z.mean = mrpt::poses::CPose2D(rel.x() + o.sigma_xy * n01(rng), rel.y() + o.sigma_xy * n01(rng),
                                geometry::wrapAngle(rel.z() + o.sigma_theta * n01(rng)));
  z.cov_inv.setZero();
  z.cov_inv(0, 0) = z.cov_inv(1, 1) = 1.0 / (o.sigma_xy * o.sigma_xy);
  z.cov_inv(2, 2) = 1.0 / (o.sigma_theta * o.sigma_theta);
  return z;
}
}  // namespace

SyntheticGraph makeGridWalkGraph(const SyntheticGraphOptions& o)
{
  if (o.nodes < 2) throw std::invalid_argument("synthetic graph: needs at least 2 nodes");
  std::mt19937 rng(o.seed);
  SyntheticGraph out;
  out.truth = gridWalk(o, rng);
  const auto& t = out.truth;
  // Odometry first, so the initial estimate is its dead reckoning.
  std::vector<mrpt::poses::CPosePDFGaussianInf> odo;
  geometry::Pose2 estimate = t[0];
  out.graph.addNode(0, mrpt::poses::CPose2D(estimate.x(), estimate.y(), estimate.z()));
  for (size_t k = 1; k < o.nodes; ++k)
  {
    odo.push_back(noisyMeasurement(geometry::relativePose(t[k - 1], t[k]), o, rng));
    const auto& m = odo.back().mean;
    estimate = geometry::composePose(estimate, geometry::Pose2(m.x(), m.y(), m.phi()));
    out.graph.addNode(k, mrpt::poses::CPose2D(estimate.x(), estimate.y(), estimate.z()));
  }
  for (size_t k = 1; k < o.nodes; ++k) out.graph.addEdge(k - 1, k, odo[k - 1], EdgeKind::Consecutive);
  for (size_t back = 2; back <= o.dense_neighbours + 1; ++back)
    for (size_t k = back; k < o.nodes && out.graph.edgeCount() < o.total_edges; ++k)
      out.graph.addEdge(k - back, k, noisyMeasurement(geometry::relativePose(t[k - back], t[k]), o, rng),
                        EdgeKind::DenseNeighbour);

  std::vector<std::pair<size_t, size_t>> candidates;
  for (size_t k = 0; k < o.nodes; ++k)
    for (size_t j = 0; j + o.loop_min_gap <= k; ++j)
      if (k - j > o.dense_neighbours + 1 && (t[k] - t[j]).head<2>().norm() < o.loop_radius)
        candidates.emplace_back(j, k);
  std::shuffle(candidates.begin(), candidates.end(), rng);
  for (const auto& [j, k] : candidates)
  {
    if (out.graph.edgeCount() >= o.total_edges) break;
    out.graph.addEdge(j, k, noisyMeasurement(geometry::relativePose(t[j], t[k]), o, rng), EdgeKind::Loop);
    ++out.good_loops;
  }
  // Wrong loops: a random far-apart pair given the measurement of a true nearby pair.
  const size_t wrong = static_cast<size_t>(std::lround(o.wrong_loop_fraction * out.good_loops));
  std::uniform_int_distribution<size_t> any(0, o.nodes - 1);
  while (out.wrong_loops < wrong)
  {
    const size_t j = any(rng), k = any(rng);
    if (j == k || (t[k] - t[j]).head<2>().norm() < 3.0) continue;
    const auto& [cj, ck] = candidates.empty() ? std::make_pair(size_t(0), size_t(1))
                                              : candidates[any(rng) % candidates.size()];
    out.graph.addEdge(j, k, noisyMeasurement(geometry::relativePose(t[cj], t[ck]), o, rng), EdgeKind::Loop);
    ++out.wrong_loops;
  }
  return out;
}

std::vector<size_t> addFalseLoops(PoseGraph& graph, const FalseLoopOptions& o)
{
  const std::vector<PoseGraph::TNodeID> ids = graph.nodeIds();
  const size_t run = o.grouped ? std::max<size_t>(o.group_size, 1) : 1;
  if (ids.size() < run + o.min_gap + 1)
    throw std::invalid_argument("false loops: the graph has " + std::to_string(ids.size()) + " nodes, fewer than " +
                                std::to_string(run + o.min_gap + 1));
  mrpt::math::CMatrixDouble33 info;
  info.setZero();
  info(0, 0) = info(1, 1) = 1 / (0.05 * 0.05);
  info(2, 2) = 1 / (0.01 * 0.01);
  std::vector<std::pair<double, size_t>> loops;  // (trace of the information, edge)
  for (size_t k = 0; k < graph.edgeCount(); ++k)
    if (graph.edge(k).kind == EdgeKind::Loop) loops.emplace_back(graph.edge(k).measurement->cov_inv.trace(), k);
  if (!loops.empty())
  {
    std::nth_element(loops.begin(), loops.begin() + loops.size() / 2, loops.end());
    info = graph.edge(loops[loops.size() / 2].second).measurement->cov_inv;
  }
  std::mt19937 rng(o.seed);
  std::uniform_int_distribution<size_t> start(0, ids.size() - run);
  std::uniform_real_distribution<double> offset(-o.max_offset, o.max_offset), angle(-M_PI, M_PI);
  std::vector<size_t> added;
  while (added.size() < o.count)
  {
    const size_t a = start(rng), b = start(rng);
    if ((a > b ? a - b : b - a) < o.min_gap) continue;
    mrpt::poses::CPosePDFGaussianInf z;
    z.mean = mrpt::poses::CPose2D(offset(rng), offset(rng), angle(rng));
    z.cov_inv = info;
    for (size_t t = 0; t < run && added.size() < o.count; ++t)
      added.push_back(*graph.addEdge(ids[a + t], ids[b + t], z, EdgeKind::Loop));
  }
  return added;
}

size_t loopEdgeCount(const PoseGraph& graph)
{
  size_t n = 0;
  for (size_t k = 0; k < graph.edgeCount(); ++k) n += graph.edge(k).kind == EdgeKind::Loop;
  return n;
}

std::vector<geometry::Pose2> truthFromGraph(const PoseGraph& graph)
{
  std::vector<geometry::Pose2> truth;
  for (const auto id : graph.nodeIds())
  {
    if (id != truth.size())
      throw std::invalid_argument("truthFromGraph: node ids must be 0..n-1, found " + std::to_string(id));
    const auto& p = graph.pose(id);
    truth.emplace_back(p.x(), p.y(), p.phi());
  }
  return truth;
}

TruthError compareToTruth(const PoseGraph& graph, const std::vector<geometry::Pose2>& truth)
{
  TruthError err;
  double sum_xy = 0, sum_th = 0;
  for (const auto id : graph.nodeIds())
  {
    if (id >= truth.size())
      throw std::invalid_argument("compareToTruth: no truth for node " + std::to_string(id));
    const auto& p = graph.pose(id);
    const double dxy = std::hypot(p.x() - truth[id].x(), p.y() - truth[id].y());
    const double dth = geometry::wrapAngle(p.phi() - truth[id].z());
    sum_xy += dxy * dxy;
    sum_th += dth * dth;
    err.max_xy = std::max(err.max_xy, dxy);
  }
  const double n = std::max<size_t>(1, graph.nodeCount());
  err.rmse_xy = std::sqrt(sum_xy / n);
  err.rmse_theta = std::sqrt(sum_th / n);
  return err;
}

}  // namespace swslam::graph

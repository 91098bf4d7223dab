// The first-order change of the truncated cost by one switch (single_flip.h) against the slow
// way: least squares re-run with the edge removed or added, on a small loop of poses with a
// few loop edges, noisy.
#include <swslam/graph/single_flip.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace swslam::graph;
using swslam::geometry::Pose2;

namespace
{
/** 16 poses around a square of 4 m sides, consecutive edges and three loops, measured with
 * noise of 3 cm and 0.5 degrees; the guess is the truth. */
GraphProblem square(std::mt19937& rng)
{
  std::normal_distribution<double> N(0, 1);
  GraphProblem p;
  for (int k = 0; k < 16; ++k)
  {
    const int side = k / 4, step = k % 4;
    const double heading = side * M_PI / 2;
    const Pose2 corner[4] = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}};
    p.poses.emplace_back(corner[side].x() + step * std::cos(heading), corner[side].y() + step * std::sin(heading), heading);
  }
  p.fixed.assign(p.poses.size(), 0);
  p.fixed[0] = 1;
  const double sxy = 0.03, sth = 0.5 * M_PI / 180;
  auto measure = [&](int i, int j, EdgeKind kind) {
    GraphProblem::Edge e;
    e.i = i;
    e.j = j;
    Pose2 z = swslam::geometry::relativePose(p.poses[i], p.poses[j]);
    z += Pose2(sxy * N(rng), sxy * N(rng), sth * N(rng));
    e.z = z;
    e.information = Eigen::Vector3d(1 / (sxy * sxy), 1 / (sxy * sxy), 1 / (sth * sth)).asDiagonal();
    e.robust = true;
    e.kind = kind;
    p.edges.push_back(e);
  };
  for (int k = 0; k + 1 < 16; ++k) measure(k, k + 1, EdgeKind::Consecutive);
  measure(15, 0, EdgeKind::Loop);
  measure(13, 2, EdgeKind::Loop);
  measure(11, 5, EdgeKind::Loop);
  return p;
}

GraphOptimizerParams leastSquares()
{
  GraphOptimizerParams l2;
  l2.kernel_alpha = 2;
  l2.relative_cost_tolerance = 1e-14;
  l2.max_iterations = 200;
  return l2;
}

/** The least-squares optimum of the kept edges and its chi2 over them. */
double optimum(GraphProblem& p, const std::vector<char>& kept)
{
  GraphProblem sub = p;
  sub.edges.clear();
  for (size_t k = 0; k < p.edges.size(); ++k)
    if (kept[k]) sub.edges.push_back(p.edges[k]);
  optimizeGraphProblem(sub, leastSquares());
  p.poses = sub.poses;
  return graphChi2(sub);
}
}  // namespace

TEST(SingleFlip, RemovingAKeptEdgeAsLeastSquaresWithoutIt)
{
  std::mt19937 rng(3);
  GraphProblem p = square(rng);
  const std::vector<char> all(p.edges.size(), 1);
  const double chi2 = optimum(p, all);
  const OutlierGates gates;
  std::vector<size_t> candidates(p.edges.size());
  for (size_t k = 0; k < candidates.size(); ++k) candidates[k] = k;
  const std::vector<double> change = singleFlipChanges(p, all, candidates, gates);
  for (size_t k = 0; k < p.edges.size(); ++k)
  {
    GraphProblem without = p;
    std::vector<char> kept = all;
    kept[k] = 0;
    const double drop = chi2 - optimum(without, kept);
    const double gate2 = gates.of(p.edges[k]) * gates.of(p.edges[k]);
    EXPECT_NEAR(gate2 - change[k], drop, 1e-3 * (1 + drop)) << "edge " << k;
  }
}

TEST(SingleFlip, AddingASwitchedOffEdgeAsLeastSquaresWithIt)
{
  std::mt19937 rng(4);
  GraphProblem p = square(rng);
  // A loop 0.4 m and 3 degrees off, switched off.
  GraphProblem::Edge wrong = p.edges.back();
  wrong.i = 9;
  wrong.j = 1;
  wrong.z = swslam::geometry::relativePose(p.poses[9], p.poses[1]) + Pose2(0.4, -0.2, 0.05);
  p.edges.push_back(wrong);
  std::vector<char> kept(p.edges.size(), 1);
  kept.back() = 0;
  const double chi2 = optimum(p, kept);
  const std::vector<double> change = singleFlipChanges(p, kept, {p.edges.size() - 1}, OutlierGates{});
  GraphProblem with = p;
  const double rise = optimum(with, std::vector<char>(p.edges.size(), 1)) - chi2;
  const OutlierGates gates;
  EXPECT_GT(rise, gates.loop * gates.loop);  // an outlier: it costs more kept than switched off
  EXPECT_NEAR(change[0] + gates.loop * gates.loop, rise, 0.05 * rise);
}

TEST(SingleFlip, AnEdgeAloneBetweenTwoPartsIsFreeToAddAndGainsNothingByLeaving)
{
  std::mt19937 rng(5);
  GraphProblem p = square(rng);
  // Without the consecutive edge 7 -> 8 and the loops across it, 8..15 hang on the loop 15 -> 0
  // only: kept, it is fitted exactly; switched off, nothing ties the parts.
  std::vector<char> kept(p.edges.size(), 1);
  kept[7] = kept[16] = kept[17] = 0;
  optimum(p, kept);
  const OutlierGates gates;
  const std::vector<double> change = singleFlipChanges(p, kept, {15, 7}, gates);
  EXPECT_DOUBLE_EQ(change[0], gates.loop * gates.loop);
  kept[15] = 0;
  EXPECT_DOUBLE_EQ(singleFlipChanges(p, kept, {15}, gates)[0], -gates.loop * gates.loop);
}

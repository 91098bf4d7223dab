// The elimination order of the 3x3 blocks of pose-graph normal equations: a permutation,
// the hub of a star last (no fill at all), and on a valley-like walk a factor about as
// sparse as with AMD on the scalar pattern and far sparser than in a random order.
#include <swslam/graph/block_amd_ordering.h>
#include <swslam/graph/synthetic.h>

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace
{
using Pairs = std::vector<std::pair<int, int>>;

/** Upper triangle of a block-sparse SPD (diagonally dominant) matrix: dense 3x3 blocks on
 * the diagonal and at every pair, block b moved to position[b]. */
Eigen::SparseMatrix<double> upperBlockMatrix(int blocks, const Pairs& pairs,
                                             const std::vector<int>& position)
{
  std::vector<Eigen::Triplet<double>> t;
  auto block = [&](int a, int b, double v, double diagonal) {
    const int lo = std::min(position[a], position[b]), hi = std::max(position[a], position[b]);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        if (3 * lo + r <= 3 * hi + c) t.emplace_back(3 * lo + r, 3 * hi + c, r == c ? diagonal : v);
  };
  for (int a = 0; a < blocks; ++a) block(a, a, 1.0, 100.0);
  for (const auto& [a, b] : pairs) block(a, b, 0.1, 0.1);
  Eigen::SparseMatrix<double> m(3 * blocks, 3 * blocks);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

using NaturalLdlt =
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper, Eigen::NaturalOrdering<int>>;
using ScalarAmdLdlt = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper>;

template <typename Solver>
double factorNonZeros(const Eigen::SparseMatrix<double>& upper)
{
  Solver s;
  s.compute(upper);
  EXPECT_EQ(s.info(), Eigen::Success);
  return static_cast<double>(Eigen::SparseMatrix<double>(s.matrixL()).nonZeros());
}

std::vector<int> identity(int n)
{
  std::vector<int> v(static_cast<size_t>(n));
  std::iota(v.begin(), v.end(), 0);
  return v;
}
}  // namespace

TEST(BlockAmdOrder, StarHubGoesLastAndNothingFillsIn)
{
  // Block 0 is coupled to every other block: eliminating it first would fill the whole
  // matrix, eliminating it last fills nothing.
  const int blocks = 40;
  Pairs star;
  for (int b = 1; b < blocks; ++b) star.emplace_back(0, b);
  const std::vector<int> position = swslam::graph::amdBlockOrder(blocks, star);
  EXPECT_EQ(position[0], blocks - 1);
  const auto ordered = upperBlockMatrix(blocks, star, position);
  const double pattern_lower = (ordered.nonZeros() - 3 * blocks) + 3 * blocks;  // incl. diagonal
  EXPECT_EQ(factorNonZeros<NaturalLdlt>(ordered), pattern_lower);
  EXPECT_GT(factorNonZeros<NaturalLdlt>(upperBlockMatrix(blocks, star, identity(blocks))),
            10 * pattern_lower);
}

TEST(BlockAmdOrder, ValleyLikeWalkFillsAboutAsLittleAsScalarAmd)
{
  // A long walk, each node coupled to its 4 predecessors, with loops (as the valley's
  // dense-neighbour graph).
  swslam::graph::SyntheticGraphOptions o;
  o.nodes = 600;
  o.total_edges = 3000;
  o.dense_neighbours = 4;
  o.seed = 5;
  const swslam::graph::PoseGraph g = swslam::graph::makeGridWalkGraph(o).graph;
  Pairs pairs;
  for (size_t k = 0; k < g.edgeCount(); ++k)
    pairs.emplace_back(static_cast<int>(g.edge(k).from), static_cast<int>(g.edge(k).to));
  const int blocks = static_cast<int>(o.nodes);
  const std::vector<int> position = swslam::graph::amdBlockOrder(blocks, pairs);

  std::vector<int> sorted = position;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, identity(blocks));  // a permutation

  const auto own_order = upperBlockMatrix(blocks, pairs, identity(blocks));
  const double block_amd = factorNonZeros<NaturalLdlt>(upperBlockMatrix(blocks, pairs, position));
  const double scalar_amd = factorNonZeros<ScalarAmdLdlt>(own_order);
  std::vector<int> shuffled = identity(blocks);
  std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(8));
  const double random = factorNonZeros<NaturalLdlt>(upperBlockMatrix(blocks, pairs, shuffled));
  EXPECT_LT(block_amd, 1.25 * scalar_amd) << "block " << block_amd << ", scalar " << scalar_amd;
  EXPECT_LT(block_amd, 0.25 * random) << "block " << block_amd << ", random " << random;
}

TEST(BlockAmdOrder, DuplicatedReversedAndDiagonalPairsChangeNothing)
{
  const Pairs once = {{0, 1}, {1, 2}, {2, 3}, {0, 3}, {3, 4}};
  Pairs messy = once;
  for (const auto& [a, b] : once) messy.emplace_back(b, a), messy.emplace_back(a, a);
  EXPECT_EQ(swslam::graph::amdBlockOrder(5, once), swslam::graph::amdBlockOrder(5, messy));
}

TEST(BlockAmdOrder, PairOutsideTheBlocksIsAnError)
{
  EXPECT_THROW(swslam::graph::amdBlockOrder(3, {{0, 3}}), std::invalid_argument);
  EXPECT_THROW(swslam::graph::amdBlockOrder(3, {{-1, 1}}), std::invalid_argument);
  EXPECT_TRUE(swslam::graph::amdBlockOrder(0, {}).empty());
}

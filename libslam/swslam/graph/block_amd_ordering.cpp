#include <swslam/graph/block_amd_ordering.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>

#include <stdexcept>
#include <string>

namespace swslam::graph
{
std::vector<int> amdBlockOrder(int blocks, const std::vector<std::pair<int, int>>& pairs)
{
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(blocks) + 2 * pairs.size());
  for (int b = 0; b < blocks; ++b) entries.emplace_back(b, b, 1.0);
  for (const auto& [a, b] : pairs)
  {
    if (a < 0 || b < 0 || a >= blocks || b >= blocks)
      throw std::invalid_argument("amdBlockOrder: block pair (" + std::to_string(a) + ", " +
                                  std::to_string(b) + ") outside 0.." +
                                  std::to_string(blocks - 1));
    if (a == b) continue;
    entries.emplace_back(a, b, 1.0);
    entries.emplace_back(b, a, 1.0);
  }
  Eigen::SparseMatrix<double> graph(blocks, blocks);
  graph.setFromTriplets(entries.begin(), entries.end());  // duplicates sum: only the pattern matters
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> order;
  Eigen::AMDOrdering<int> amd;
  amd(graph, order);
  // Eigen's orderings give the inverse permutation: order[k] is the block eliminated k-th
  // (SimplicialCholesky applies P = order^-1 as P A P^T).
  std::vector<int> position(static_cast<size_t>(blocks));
  for (int k = 0; k < blocks; ++k) position[static_cast<size_t>(order.indices()[k])] = k;
  return position;
}

}  // namespace swslam::graph

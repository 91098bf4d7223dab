#include "swslam/block_amd_ordering.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace swslam
{
Eigen::SparseMatrix<double> blockPattern(const Eigen::SparseMatrix<double>& m, int block)
{
  if (block < 1 || m.rows() != m.cols() || m.rows() % block != 0)
    throw std::invalid_argument("blockPattern: a " + std::to_string(m.rows()) + "x" +
                                std::to_string(m.cols()) + " matrix is not made of " +
                                std::to_string(block) + "x" + std::to_string(block) + " blocks");
  const int n = static_cast<int>(m.rows()) / block;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(n) + 2 * static_cast<size_t>(m.nonZeros()) / (block * block));
  for (int b = 0; b < n; ++b) entries.emplace_back(b, b, 1.0);
  // The columns of a block column come one after the other: seen[I] == J marks block (I, J)
  // as already listed.
  std::vector<int> seen(static_cast<size_t>(n), -1);
  for (int col = 0; col < m.outerSize(); ++col)
  {
    const int col_block = col / block;
    for (Eigen::SparseMatrix<double>::InnerIterator it(m, col); it; ++it)
    {
      const int row_block = static_cast<int>(it.row()) / block;
      if (row_block == col_block || seen[row_block] == col_block) continue;
      seen[row_block] = col_block;
      entries.emplace_back(row_block, col_block, 1.0);
      entries.emplace_back(col_block, row_block, 1.0);
    }
  }
  Eigen::SparseMatrix<double> pattern(n, n);
  // Duplicates are summed: only the pattern matters.
  pattern.setFromTriplets(entries.begin(), entries.end());
  return pattern;
}

SparsePermutation expandBlockPermutation(const SparsePermutation& block_perm, int block)
{
  if (block < 1) throw std::invalid_argument("expandBlockPermutation: block must be >= 1");
  const int n = static_cast<int>(block_perm.size());
  SparsePermutation perm(n * block);
  for (int b = 0; b < n; ++b)
    for (int k = 0; k < block; ++k) perm.indices()[b * block + k] = block_perm.indices()[b] * block + k;
  return perm;
}

SparsePermutation blockAmdOrdering(const Eigen::SparseMatrix<double>& m, int block)
{
  SparsePermutation block_perm;
  Eigen::AMDOrdering<int> amd;
  amd(blockPattern(m, block), block_perm);
  return expandBlockPermutation(block_perm, block);
}

}  // namespace swslam

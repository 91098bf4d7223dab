#pragma once
// The normal equations of one optimization, kept across its stages and solves while their
// sparsity pattern holds (graduated non-convexity changes the kernel, not the pattern), with
// the edges an outlier kernel has all but switched off decoupled: such an edge keeps its
// gradient and the diagonal blocks of its Hessian, J_i^T W J_i and J_j^T W J_j, but not the
// block J_i^T W J_j that couples its two poses. Its weight is small, so the step barely
// changes, while a thousand long false loops would otherwise fill the factor in (8 times
// the non-zeros of the graph without them, doc/graph-optimization.md). Dropping the coupling
// block of a positive semi-definite edge term leaves a positive semi-definite one, so the
// system stays solvable, and the cost the step is judged by still counts every edge.

#include <swslam/graph/normal_equations.h>

#include <memory>
#include <utility>
#include <vector>

namespace swslam::graph
{
class CoupledSystem
{
 public:
  /** Starts a solve of `free_blocks` variables whose edges join the variable pairs `pairs`
   * (-1: a fixed pose). With `keep_decoupled`, the same edges as the last solve's keep
   * their coupling; otherwise every edge is coupled. The symbolic analysis is reused when
   * the analysed pattern holds the coupled pairs and at most kReuseSlack more. Throws std::invalid_argument for a block index
   * outside [-1, free_blocks). */
  NormalEquations& prepare(int free_blocks, const std::vector<std::pair<int, int>>& pairs, bool keep_decoupled);

  /** As prepare() of new pairs, but with the edges flagged in `weak` decoupled at once if
   * they are at least `min_count` (one symbolic analysis, not two). */
  NormalEquations& prepareDecoupled(int free_blocks, const std::vector<std::pair<int, int>>& pairs,
                                    const std::vector<char>& weak, size_t min_count);

  /** Decouples the coupled edges flagged in `weak` (one flag per pair of the last prepare)
   * if they are at least `min_count`, and then returns true (the normal equations are new:
   * linearize again). */
  bool decouple(const std::vector<char>& weak, size_t min_count);

  NormalEquations& equations() { return *ne_; }
  /** Whether edge n (an index into the last prepare's pairs) adds its coupling block. */
  bool coupled(size_t n) const { return coupled_[n] != 0; }
  /** Edges with both ends free that are decoupled. */
  size_t decoupled() const { return decoupled_; }
  /** Symbolic analyses so far (a new pattern each). */
  size_t analyses() const { return analyses_; }

  /** The analysed pattern is reused for coupled pairs it holds if it has at most this share
   * of pairs more (least squares on the edges kept after a few false loops). */
  static constexpr double kReuseSlack = 0.01;

 private:
  /** The normal equations of the coupled edges, rebuilt if their pairs changed. */
  void build();
  /** decouple(), building only if something was decoupled. */
  bool markDecoupled(const std::vector<char>& weak, size_t min_count);

  int free_blocks_ = -1;
  std::vector<std::pair<int, int>> pairs_, coupled_pairs_;
  std::vector<char> coupled_;
  size_t decoupled_ = 0, analyses_ = 0;
  std::unique_ptr<NormalEquations> ne_;
};

}  // namespace swslam::graph

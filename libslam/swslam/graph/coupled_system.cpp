#include <swslam/graph/coupled_system.h>

#include <algorithm>

namespace swslam::graph
{
NormalEquations& CoupledSystem::prepare(int free_blocks, const std::vector<std::pair<int, int>>& pairs,
                                        bool keep_decoupled)
{
  if (!keep_decoupled || !ne_ || free_blocks != free_blocks_ || pairs != pairs_)
  {
    pairs_ = pairs;
    free_blocks_ = free_blocks;
    coupled_.assign(pairs_.size(), 1);
  }
  build();
  return *ne_;
}

NormalEquations& CoupledSystem::prepareDecoupled(int free_blocks, const std::vector<std::pair<int, int>>& pairs,
                                                 const std::vector<char>& weak, size_t min_count)
{
  pairs_ = pairs;
  free_blocks_ = free_blocks;
  coupled_.assign(pairs_.size(), 1);
  if (!markDecoupled(weak, min_count)) build();
  return *ne_;
}

bool CoupledSystem::decouple(const std::vector<char>& weak, size_t min_count)
{
  return markDecoupled(weak, min_count);
}

bool CoupledSystem::markDecoupled(const std::vector<char>& weak, size_t min_count)
{
  size_t count = 0;
  auto both_free = [&](size_t n) { return pairs_[n].first >= 0 && pairs_[n].second >= 0; };
  for (size_t n = 0; n < coupled_.size(); ++n) count += coupled_[n] && weak[n] && both_free(n);
  if (count == 0 || count < min_count) return false;
  for (size_t n = 0; n < coupled_.size(); ++n)
    if (weak[n] && both_free(n)) coupled_[n] = 0;
  build();
  return true;
}

void CoupledSystem::build()
{
  std::vector<std::pair<int, int>> kept;
  decoupled_ = 0;
  for (size_t n = 0; n < pairs_.size(); ++n)
  {
    const bool both_free = pairs_[n].first >= 0 && pairs_[n].second >= 0;
    if (both_free && coupled_[n])
      kept.push_back(pairs_[n]);
    else
      decoupled_ += both_free;
  }
  // Each pair once, as (lower, higher) block.
  for (auto& [a, b] : kept)
    if (a > b) std::swap(a, b);
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  // The analysed pattern is kept if it holds the new pairs and not many more: a few extra
  // pairs (structural zeros) cost less fill-in than a new analysis.
  const size_t slack = static_cast<size_t>(kReuseSlack * static_cast<double>(coupled_pairs_.size()));
  if (ne_ && kept.size() <= coupled_pairs_.size() && kept.size() + slack >= coupled_pairs_.size() &&
      std::includes(coupled_pairs_.begin(), coupled_pairs_.end(), kept.begin(), kept.end()))
    return;
  ne_ = std::make_unique<NormalEquations>(free_blocks_, kept);  // checks the pairs
  coupled_pairs_.swap(kept);
  ++analyses_;
}

}  // namespace swslam::graph

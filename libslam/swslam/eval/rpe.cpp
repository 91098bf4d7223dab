#include <swslam/eval/rpe.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace swslam::eval
{
std::vector<IndexPair> consecutivePairs(size_t n)
{
  std::vector<IndexPair> out;
  for (size_t i = 0; i + 1 < n; i++) out.push_back({i, i + 1});
  return out;
}

std::vector<IndexPair> distancePairs(const std::vector<PosePair>& pairs, double min_distance)
{
  // Path length from the start at every pose; two pointers over it.
  std::vector<double> s(pairs.size(), 0.0);
  for (size_t k = 1; k < pairs.size(); k++)
    s[k] = s[k - 1] + pairs[k].gt.distanceTo(pairs[k - 1].gt);
  std::vector<IndexPair> out;
  size_t j = 1;
  for (size_t i = 0; i < pairs.size(); i++)
  {
    j = std::max(j, i + 1);
    while (j < pairs.size() && s[j] - s[i] < min_distance) j++;
    if (j == pairs.size()) break;
    out.push_back({i, j});
  }
  return out;
}

mrpt::poses::CPose2D relativeError(const mrpt::poses::CPose2D& a_i,
                                   const mrpt::poses::CPose2D& a_j,
                                   const mrpt::poses::CPose2D& expected)
{
  // MRPT's a - b is b^-1 (+) a.
  return (a_j - a_i) - expected;
}

RpeResult relativePoseError(const std::vector<PosePair>& pairs,
                            const std::vector<IndexPair>& segments)
{
  std::vector<double> trans, rot;
  size_t within = 0;
  for (const auto& [i, j] : segments)
  {
    const auto e = relativeError(pairs[i].est, pairs[j].est, pairs[j].gt - pairs[i].gt);
    trans.push_back(e.norm());
    rot.push_back(std::abs(mrpt::math::wrapToPi(e.phi())));
    within += trans.back() < geometry::kMotionAgreement ? 1 : 0;
  }
  const double share = segments.empty() ? std::nan("") : within / static_cast<double>(segments.size());
  return {errorStats(std::move(trans)), errorStats(std::move(rot)), share};
}

}  // namespace swslam::eval

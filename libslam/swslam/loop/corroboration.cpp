#include <swslam/loop/corroboration.h>

#include <swslam/loop/closer.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace swslam::loop
{
using mrpt::poses::CPose2D;

std::vector<graph::Constraint> LoopCorroboration::add(size_t newest, const std::vector<graph::Constraint>& verified,
                                                const std::function<CPose2D(size_t)>& pose,
                                                const std::function<double(size_t)>& path_length)
{
  const auto w = static_cast<size_t>(std::max(0, params_.consistency_window));
  if (w == 0) return verified;
  pending_.erase(std::remove_if(pending_.begin(), pending_.end(),
                                [&](const Pending& p) { return p.edge.to + w < newest; }),
                 pending_.end());
  auto near = [w](size_t a, size_t b) { return (a > b ? a - b : b - a) <= w; };
  std::vector<graph::Constraint> out;
  for (const graph::Constraint& e : verified)
  {
    Pending v;
    v.edge = e;
    v.measure = LoopEdgeMeasure{e.from, e.to, e.z, e.information.inverse()};
    for (Pending& p : pending_)
    {
      if (!near(p.edge.from, e.from) || !near(p.edge.to, e.to)) continue;
      const LoopEdgeMeasure& l1 = p.measure;  // a -> n; e is b -> m
      const CPose2D rel_ab = pose(e.from) - pose(l1.from);
      const CPose2D rel_nm = pose(e.to) - pose(l1.to);
      const double path = std::abs(path_length(e.from) - path_length(l1.from)) +
                          std::abs(path_length(e.to) - path_length(l1.to));
      const Eigen::Matrix3d local = driftCovariance(path, params_);
      if (!(loopPairChi2(l1, v.measure, rel_ab, rel_nm, std::sqrt(local(0, 0)),
                         std::sqrt(local(2, 2))) <= params_.chi2_gate))
        continue;
      if (!p.added) out.push_back(p.edge);
      p.added = true;
      v.added = true;
    }
    if (v.added) out.push_back(e);
    pending_.push_back(v);
  }
  return out;
}

}  // namespace swslam::loop

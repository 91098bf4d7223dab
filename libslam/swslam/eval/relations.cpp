#include <swslam/eval/relations.h>

#include <swslam/eval/association.h>
#include <swslam/eval/rpe.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace swslam::eval
{
RelationsResult relationsError(const std::vector<common::StampedPose>& est_in,
                               const std::vector<Relation>& relations, double max_dt)
{
  const auto est = sortedByTime(est_in);
  RelationsResult r;
  std::vector<double> trans, trans_sq, rot, rot_sq;
  for (const auto& rel : relations)
  {
    const auto i = closestInTime(est, rel.t1, max_dt);
    const auto j = closestInTime(est, rel.t2, max_dt);
    if (!i || !j)
    {
      r.unmatched++;
      continue;
    }
    r.used++;
    if (!rel.planar) r.nonplanar++;
    const auto e = relativeError(est[*i].pose, est[*j].pose, rel.delta);
    const double t = e.norm(), a = std::abs(mrpt::math::wrapToPi(e.phi()));
    trans.push_back(t);
    trans_sq.push_back(t * t);
    rot.push_back(a);
    rot_sq.push_back(a * a);
  }
  r.translation = errorStats(std::move(trans));
  r.translation_sq = errorStats(std::move(trans_sq));
  r.rotation = errorStats(std::move(rot));
  r.rotation_sq = errorStats(std::move(rot_sq));
  return r;
}

}  // namespace swslam::eval

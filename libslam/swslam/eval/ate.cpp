#include <swslam/eval/ate.h>

#include <swslam/eval/se2_alignment.h>

#include <stdexcept>

namespace swslam::eval
{
AteResult absoluteTrajectoryError(const std::vector<PosePair>& pairs)
{
  if (pairs.empty()) throw std::invalid_argument("ATE: no associated poses");
  std::vector<Eigen::Vector2d> est, gt;
  for (const auto& p : pairs)
  {
    est.emplace_back(p.est.x(), p.est.y());
    gt.emplace_back(p.gt.x(), p.gt.y());
  }
  AteResult r;
  r.alignment = alignSE2(est, gt);
  std::vector<double> errors;
  for (size_t i = 0; i < pairs.size(); i++)
  {
    double x, y;
    r.alignment.composePoint(est[i].x(), est[i].y(), x, y);
    errors.push_back((gt[i] - Eigen::Vector2d(x, y)).norm());
  }
  r.position = errorStats(std::move(errors));
  return r;
}

}  // namespace swslam::eval

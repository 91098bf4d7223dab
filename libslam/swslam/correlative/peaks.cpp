#include <swslam/correlative/peaks.h>

namespace swslam::correlative
{
double peakRadius(double sigma, double resolution) { return 3 * sigma + resolution; }

std::optional<SecondPeak> secondPeak(const ScorePyramid& pyramid, const std::vector<Eigen::Vector2d>& points,
                                     SearchWindow w, const Eigen::Vector3d& chosen, double radius,
                                     double min_score, double margin, std::optional<double> chosen_objective)
{
  w.exclude_xy = chosen.head<2>();
  w.exclude_radius = radius;
  const auto other = searchBranchAndBound(pyramid, points, w, min_score);
  if (!other) return std::nullopt;
  SecondPeak out;
  out.peak = *other;
  out.chosen_objective =
      chosen_objective ? *chosen_objective : objective(w, scoreAt(pyramid.levels.front(), points, chosen), chosen);
  out.similar = other->objective >= out.chosen_objective - margin;
  return out;
}

}  // namespace swslam::correlative

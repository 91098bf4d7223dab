#pragma once
// A second peak of the correlative objective (doc/tracking.md, "Ambiguous matches"): a
// symmetric room or a repeated structure scores a scan about as well at two poses far apart,
// and a match there is ambiguous between them, whichever of the two it took.

#include <swslam/correlative/search.h>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace swslam::correlative
{
struct SecondPeak
{
  SearchResult peak;       ///< the best pose of the window outside the chosen pose's peak
  double chosen_objective = 0;  ///< the chosen pose's own objective
  bool similar = false;    ///< the second peak's objective is within `margin` of the chosen's
};

/** The radius of one peak of the score: a point keeps most of its score within 3 kernel
 * sigmas of its cell, and a pose one cell off still shares the peak: 3 sigma + resolution. */
double peakRadius(double sigma, double resolution);

/** Searches `w` again with the disc of `radius` around `chosen` (a pose [x, y, theta] of the
 * grid's frame) excluded, and compares that best pose's objective with the chosen pose's:
 * `chosen_objective` when the caller has it (a search's own best), else
 * objective(w, scoreAt(...), chosen). `similar` when it is at least the chosen's less
 * `margin`. Nothing when no pose outside the disc scores min_score. Tracking and loop
 * verification both tell an ambiguous match by it. */
std::optional<SecondPeak> secondPeak(const ScorePyramid& pyramid, const std::vector<Eigen::Vector2d>& points,
                                     SearchWindow w, const Eigen::Vector3d& chosen, double radius,
                                     double min_score, double margin,
                                     std::optional<double> chosen_objective = std::nullopt);

}  // namespace swslam::correlative

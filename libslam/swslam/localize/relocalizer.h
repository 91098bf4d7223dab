#pragma once
// Global relocalization: where on the saved map a scan can have been taken, with no guess.
// The scan's points are searched over the whole map and every heading by the correlative
// search's branch and bound (Hess et al. 2016, as Cartographer's global constraint search),
// on the score grid of the map's occupied and free cells; the best pose elsewhere tells a
// distinct place from an ambiguous one. The caller verifies the pose by PLICP (localizer.h).

#include <swslam/correlative/score_grid.h>
#include <swslam/correlative/search.h>
#include <swslam/localize/params.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace swslam::localize
{
/** A scan's place on the map, from the whole-map search. */
struct PlaceCandidate
{
  Eigen::Vector3d pose = Eigen::Vector3d::Zero();  ///< sensor pose [x, y, theta] in the map frame
  double score = 0;   ///< mean score of the points there
  double second = 0;  ///< the best score farther than ambiguity_radius (0: none above the floor)
  bool distinct = false;  ///< score >= min_score and second <= max_second_ratio score
};

class Relocalizer
{
 public:
  /** The pyramid of the grid's occupied and free cells (thresholds from [map]; free cells
   * score -1). Throws std::invalid_argument for a grid with no occupied cell, and
   * std::length_error for one too large to search (kMaxPyramidCells). */
  Relocalizer(const mrpt::maps::COccupancyGridMap2D& grid, double occupied_thresh, double free_thresh,
              const LocalizationParams& params);

  /** The best pose of `points` (sensor frame) on the whole map, and the best one elsewhere;
   * none when no pose scores at least min_score. */
  std::optional<PlaceCandidate> find(const std::vector<Eigen::Vector2d>& points) const;

  double resolution() const { return pyramid_.levels[0].resolution; }
  /** The map's score grid (the pyramid's base). */
  const correlative::ScoreGrid& grid() const { return pyramid_.levels[0]; }
  /** The windows that together cover the map (one unless it is more than 400 m across at
   * 0.2 m cells). */
  const std::vector<correlative::SearchWindow>& windows() const { return windows_; }

 private:
  std::optional<correlative::SearchResult> best(const std::vector<Eigen::Vector2d>& points, double min_score,
                                                const std::optional<Eigen::Vector2d>& exclude) const;

  LocalizationParams params_;
  correlative::ScorePyramid pyramid_;
  std::vector<correlative::SearchWindow> windows_;
};

/** Pyramid levels above the base of the whole-map search: its top level's cells are
 * 2^kPyramidDepth map cells wide (25.6 m at 0.2 m), which bounds the grid's padding. */
inline constexpr int kPyramidDepth = 7;

}  // namespace swslam::localize

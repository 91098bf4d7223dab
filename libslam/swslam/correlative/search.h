#pragma once
// Correlative scan matching by branch and bound (Olson 2009; Hess et al. 2016): the pose in a
// window of translations and rotations that puts a scan's points on the best cells of a
// reference's score grid, less a cost for its distance from the window's centre (the motion
// prior). Exact over the window's lattice: the same best objective as trying every pose
// (searchBruteForce), at a fraction of the cost.

#include <swslam/correlative/score_grid.h>

#include <Eigen/Core>

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace swslam::correlative
{
/** A window's translations: at most +-this many cells on each axis ([correlative] allows 256);
 * a wider window (its bound tables grow with its square) throws std::invalid_argument. */
constexpr int kMaxWindowCells = 1024;
/** A window's rotations: at most this many in a turn (a step of 0.1 degree, [correlative]'s
 * smallest); a finer step throws std::invalid_argument. */
constexpr int kMaxWindowAngles = 3600;

/** The poses tried: rotations theta = centre.z + k theta_step within +-half_theta (the whole
 * circle once when half_theta >= pi, the step then shortened to divide it evenly), and for each
 * the translations centre.xy + (i, j) * resolution with |i|, |j| <= half_xy / resolution.
 * A pose [x, y, theta] maps a point p to R(theta) p + (x, y) in the grid's frame. */
struct SearchWindow
{
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double half_xy = 2.0;                   ///< [m]
  double half_theta = M_PI;               ///< [rad]
  double theta_step = 1.0 * M_PI / 180;   ///< [rad]
  double cost_per_m = 0;    ///< objective = score - cost_per_m |t - centre.xy| ...
  double cost_per_rad = 0;  ///< ... - cost_per_rad |theta - centre.z|
  double cost_per_m2 = 0;   ///< ... - cost_per_m2 |t - centre.xy|^2 (a Gaussian prior)
  /** Poses whose translation is within exclude_radius of exclude_xy are not results (< 0:
   * none excluded): the best pose elsewhere, to tell a distinct optimum from an ambiguous one. */
  Eigen::Vector2d exclude_xy = Eigen::Vector2d::Zero();
  double exclude_radius = -1;  ///< [m]
};

/** True if the translation t is inside the window's excluded disc. */
bool excluded(const SearchWindow& w, const Eigen::Vector2d& t);

/** The objective of a pose: its score less the window's costs of its offset from the centre. */
double objective(const SearchWindow& w, double score, const Eigen::Vector3d& pose);

struct SearchResult
{
  Eigen::Vector3d pose = Eigen::Vector3d::Zero();
  double score = 0;             ///< mean cell value of the points / 255, in [-1, 1] (free space < 0)
  double objective = 0;         ///< the score less the costs (what the search maximises)
  size_t bounds_evaluated = 0;  ///< candidates scored (any level): the search's cost
  /** Per pyramid level h (index h, up to the search's top level): the candidates scored at
   * it, and those of them split into their four children (neither pruned by their bound nor
   * left for min_score). Branch and bound only. */
  std::vector<size_t> evaluated_by_level, expanded_by_level;
};

/** The window's rotations, in the order searched. Throws std::invalid_argument for a step that
 * is not positive or gives more than kMaxWindowAngles in a turn. */
std::vector<double> windowAngles(const SearchWindow& w);

/** The pose of the window's lattice with the best objective among those whose score is at
 * least `min_score` and whose objective exceeds `min_objective`, if any. A floor prunes early:
 * a caller that only wants poses better than one it has (tracking's first match) passes its
 * objective.
 * Level 0 cells are looked up as grid.cellOf(R(theta) p + centre.xy) + (i, j). The pyramid's
 * depth bounds the search's top level (deeper levels are not needed beyond the window). */
std::optional<SearchResult> searchBranchAndBound(
    const ScorePyramid& pyramid, const std::vector<Eigen::Vector2d>& points, const SearchWindow& w,
    double min_score, double min_objective = -std::numeric_limits<double>::infinity());

/** Slow, obviously correct version: scores every pose of the lattice; ties go to the first
 * in the order angle, then i, then j. Same best objective as searchBranchAndBound(). */
std::optional<SearchResult> searchBruteForce(
    const ScoreGrid& grid, const std::vector<Eigen::Vector2d>& points, const SearchWindow& w,
    double min_score, double min_objective = -std::numeric_limits<double>::infinity());

/** Score of an arbitrary pose: the mean of grid.at(cellOf(R p + t)) / 255 over the points
 * (0 for no points). */
double scoreAt(const ScoreGrid& grid, const std::vector<Eigen::Vector2d>& points,
               const Eigen::Vector3d& pose);

/** Two poses' scores on the points that can tell them apart. A cell is known when it is
 * non-zero (near a reference hit, or free space); a point in an unknown cell neither supports
 * nor contradicts a pose. Left out: a point unknown at both poses, and a point unknown at one
 * pose whose cell at the other lies on a surface that goes on past it, away from the first
 * cell (the cell as far beyond scores at least goes_on_ratio times as much): a wall that the
 * reference saw only so far supports a pose that pulls the point onto it no more than it would
 * the other, had the reference seen farther. A point on a surface that ends there (a post, a
 * corner) is kept: unknown at one pose, it is evidence for the other. */
struct CommonScores
{
  size_t points = 0;    ///< points compared
  double a = 0, b = 0;  ///< their mean cell value / 255 at each pose (0 for no points)
};
CommonScores commonScores(const ScoreGrid& grid, const std::vector<Eigen::Vector2d>& points,
                          const Eigen::Vector3d& a, const Eigen::Vector3d& b, double goes_on_ratio);

/** Two poses' objectives (score on the grid less the window's motion prior) on the points
 * that can tell them apart (commonScores, with goes_on_ratio) when at least
 * common_points_fraction of the points are (and some are), else on all the points (scoreAt).
 * How the choice between two matches of a scan compares them. */
struct MatchComparison
{
  double a = 0, b = 0;       ///< the objectives at pose a and pose b
  size_t common_points = 0;  ///< the points compared on (0: all of them)
};
MatchComparison compareMatches(const ScoreGrid& grid, const std::vector<Eigen::Vector2d>& points,
                               const SearchWindow& w, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               double common_points_fraction, double goes_on_ratio);

/** Pyramid depth needed for a window: the smallest h with 2^h >= 2 half_xy / resolution + 1.
 * Throws std::invalid_argument beyond kMaxWindowCells. */
int depthForWindow(double half_xy, double resolution);

}  // namespace swslam::correlative

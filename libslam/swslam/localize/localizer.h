#pragma once
// Localization on a saved map (doc/localization.md): each scan is matched against the map's
// node nearest its predicted pose (tracking's scan matcher: PLICP, with the correlative
// search when the first match calls for it); the map and its nodes never move. With no
// initial pose, or once the scans have gone unmatched for lost_after seconds, the state is
// lost and the whole map is searched (relocalizer.h) every relocalize_interval seconds of
// log; a distinct place found is verified by the same match before it is believed.

#include <swslam/correlative/params.h>
#include <swslam/localize/map_nodes.h>
#include <swslam/localize/params.h>
#include <swslam/localize/relocalizer.h>
#include <swslam/plicp/params.h>
#include <swslam/sensor/scan_input.h>
#include <swslam/tracking/params.h>
#include <swslam/tracking/scan_matcher.h>

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace swslam::localize
{
enum class LocalizationState
{
  Tracked,      ///< matched against the map from the previous pose
  Relocalized,  ///< placed by the whole-map search, verified by a match
  Predicted,    ///< the match failed: the previous pose moved by the odometry or the last motion
  Lost,         ///< no pose: not yet relocalized, or unmatched for lost_after
};
const char* toString(LocalizationState s);

/** One scan's result. */
struct LocalizedScan
{
  LocalizationState state = LocalizationState::Lost;
  mrpt::poses::CPose2D pose;  ///< vehicle pose in the map frame (Lost: none, zero)
  /** of pose [x, y, phi] in the map frame (Tracked, Relocalized: the match's closed-form
   * covariance; Predicted: grown by the time since the last match; Lost: infinite) */
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
  double inlier_fraction = 0;  ///< of the scan's valid rays, matched within 3 sigma of the node's surface
  double map_score = 0;        ///< mean score of the scan's points on the map's grid at the pose (-1..1; free space < 0)
  size_t node = 0;             ///< the map node matched against
  bool searched_map = false;   ///< the whole map was searched for this scan
  size_t valid_rays = 0;
};

struct LocalizerParams
{
  LocalizationParams localization;
  plicp::PlicpParams plicp;
  tracking::TrackingParams tracking;
  correlative::CorrelativeParams correlative;
};

class Localizer
{
 public:
  /** Localizes on `nodes` and `relocalizer`'s map (both outlive the localizer). */
  Localizer(const MapNodes& nodes, const Relocalizer& relocalizer, const LocalizerParams& params);

  /** Starts tracking from this vehicle pose (map frame): the next scan's pose, not lost. */
  void setInitialPose(const mrpt::poses::CPose2D& pose);

  /** Localizes one scan (its observation must have passed sensor::checkObservationGeometry). */
  LocalizedScan localize(const sensor::ScanInput& input);

 private:
  /** The match of `scan` against the node nearest `vehicle_guess` from that guess. */
  struct NodeMatch
  {
    tracking::ScanMatch match;
    size_t node = 0;
    mrpt::poses::CPose2D vehicle;  ///< the matched vehicle pose in the map frame
    Eigen::Matrix3d covariance;    ///< its covariance in the map frame
    double inlier_fraction = 0;
    bool good = false;             ///< converged, not unmatched, enough inliers
  };
  NodeMatch matchNode(const tracking::PreparedScan& scan, const mrpt::poses::CPose2D& mount,
                      const mrpt::poses::CPose2D& vehicle_guess, bool measured);
  /** The whole-map search and its verification; none if the place is not distinct or the
   * match does not confirm it. */
  std::optional<NodeMatch> relocalize(const tracking::PreparedScan& scan, const mrpt::poses::CPose2D& mount,
                                      const std::vector<Eigen::Vector2d>& map_points);
  /** The mean score of `map_points` (sensor frame) on the map's grid, the vehicle at `vehicle`. */
  double mapScore(const std::vector<Eigen::Vector2d>& map_points, const mrpt::poses::CPose2D& mount,
                  const mrpt::poses::CPose2D& vehicle) const;
  /** The vehicle's motion since the last scan, `interval` seconds ago. */
  mrpt::poses::CPose2D predictedMotion(const std::optional<mrpt::poses::CPose2D>& odometry, double interval) const;
  /** Not lost: the scan matched from the last pose moved by `motion`, or placed by the
   * prediction (and lost once that has lasted lost_after). */
  LocalizedScan track(const tracking::PreparedScan& scan, const mrpt::poses::CPose2D& mount,
                      const mrpt::poses::CPose2D& motion, double t);
  /** Lost: the whole map searched if relocalize_interval has passed since the last search. */
  LocalizedScan searchMap(const tracking::PreparedScan& scan, const mrpt::poses::CPose2D& mount,
                          const std::vector<Eigen::Vector2d>& map_points,
                          const std::optional<mrpt::poses::CPose2D>& odometry, double t);

  const MapNodes& nodes_;
  const Relocalizer& relocalizer_;
  LocalizerParams params_;
  tracking::ScanForms forms_;
  tracking::ScanMatcher matcher_;
  std::unique_ptr<tracking::Submap> submap_;
  size_t submap_node_ = 0;

  bool lost_ = true;
  mrpt::poses::CPose2D pose_;           ///< the last pose (not lost)
  mrpt::poses::CPose2D last_motion_;    ///< vehicle motion of the last scan
  Eigen::Matrix3d last_covariance_ = Eigen::Matrix3d::Identity();
  std::optional<double> last_time_, last_matched_time_, last_search_time_;
  std::optional<double> last_interval_;
};

}  // namespace swslam::localize

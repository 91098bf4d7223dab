#pragma once
// Local tracking (paper sec. II.C, Fig. 1-2; doc/tracking.md): each scan matched against the
// submap ending at the latest keyframe, from the previous relative pose moved by the expected
// motion. Past a translation or rotation threshold a new keyframe (graph node) is made; it is
// connected to the previous node and, densely, to every recent node within a radius.

#include <swslam/correlative/params.h>
#include <swslam/graph/constraint.h>
#include <swslam/plicp/plicp.h>
#include <swslam/tracking/keyframe.h>
#include <swslam/tracking/params.h>
#include <swslam/tracking/prepared_scan.h>
#include <swslam/tracking/scan_matcher.h>
#include <swslam/tracking/steady_motion.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

namespace swslam::tracking
{
/** Where the pose of a scan came from. */
enum class TrackingSource
{
  First,           ///< the first scan: the map origin
  Match,           ///< PLICP against the keyframe converged
  Searched,        ///< the prediction failed; PLICP from a correlative search's pose won
  Odometry,        ///< the match failed: previous pose moved by the odometry increment
  ConstantMotion,  ///< the match failed, no odometry: previous pose moved by the last motion
};
const char* toString(TrackingSource s);
/** Whether the match failed and a fallback (odometry or constant motion) placed the scan. */
inline bool isFallback(TrackingSource s)
{
  return s == TrackingSource::Odometry || s == TrackingSource::ConstantMotion;
}

struct TrackingStep
{
  mrpt::poses::CPose2D pose;      ///< vehicle pose of this scan in the map frame
  size_t keyframe = 0;            ///< the keyframe `relative` refers to (the new one if made)
  mrpt::poses::CPose2D relative;  ///< vehicle pose relative to that keyframe
  /** Information of `relative` from the match (vehicle frame, [x, y, theta]); zero when the
   * prediction placed the scan, and for a new keyframe (exactly on itself). */
  Eigen::Matrix3d relative_information = Eigen::Matrix3d::Zero();
  plicp::MatchResult match;  ///< the match against the keyframe, in its sensor frame (status says if it failed)
  TrackingSource source = TrackingSource::First;
  bool new_keyframe = false;
  std::vector<graph::Constraint> edges;  ///< the new node's edges
  size_t dense_matches = 0;        ///< dense-neighbour matches tried for the new node
  bool searched = false;           ///< the correlative search ran (source says if it won)
  double match_time = 0;           ///< [s] spent matching against the keyframe (search included)
  size_t valid_rays = 0;           ///< valid rays of this scan
  /** Directions the scan could not decide: the kept match's weak ones, plus one for a second
   * peak of the search, plus one for a choice the prediction made between the first and the
   * searched match (0: none) */
  int ambiguous = 0;
  /** Of those, the ones along which the prediction decided the pose: the unobservable weak
   * ones (no ray faces them), and its choice between two matches (0: none) */
  int prior_decided = 0;
};

class LocalTracker
{
 public:
  LocalTracker(const TrackingParams& tracking, const plicp::PlicpParams& plicp,
               const correlative::CorrelativeParams& correlative = correlative::CorrelativeParams());
  LocalTracker(const LocalTracker&) = delete;  // the submap's rays are gathered from this tracker
  LocalTracker& operator=(const LocalTracker&) = delete;

  /** Tracks one scan. `odometry_increment` is the vehicle motion since the previous scan, if
   * known. The observation's geometry must have passed sensor::checkObservationGeometry, as
   * every scan fed to SlamSystem has; a scan with few or no valid rays is tracked by the
   * fallback. */
  TrackingStep process(const mrpt::obs::CObservation2DRangeScan& obs,
                       const std::optional<mrpt::poses::CPose2D>& odometry_increment = std::nullopt);

  /** Continues a saved session (before the first scan): its nodes become keyframes 0..n-1 at
   * `poses`, and `observations` (one per node, null allowed for all but the last kept()) give
   * the last kept() their scans. The next scan is matched against the last keyframe from where
   * the session ended, no motion known. Throws std::logic_error after a scan, and
   * std::invalid_argument for sizes that disagree or a kept node without its observation. */
  void resume(const std::vector<mrpt::poses::CPose2D>& poses,
              const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& observations);

  /** Moves a keyframe (after graph optimization); later scans are placed relative to it. */
  void setKeyframePose(size_t id, const mrpt::poses::CPose2D& pose);

  const std::vector<Keyframe>& keyframes() const { return keyframes_; }
  /** How many of the last keyframes keep their scan: those later scans are matched against
   * (the submap's, and the dense neighbours' within dense_max_index_gap of a new node). */
  size_t kept() const;

 private:
  /** The prediction of the next scan: its vehicle pose relative to the last keyframe, and what
   * the matcher gets of it. */
  struct Predicted
  {
    mrpt::poses::CPose2D motion;    ///< vehicle motion since the previous scan
    mrpt::poses::CPose2D relative;  ///< vehicle pose relative to the last keyframe
    Prediction sensor;              ///< the same in the last keyframe's sensor frame, for the matcher
  };
  /** The previous motion at constant velocity over `interval` [s] (the paper's previous
   * roto-translation, per scan without constant_velocity), or the odometry increment. */
  Predicted predict(const std::optional<mrpt::poses::CPose2D>& odometry_increment, double interval);
  /** Where the match is ambiguous, the prediction decides (takePriorWhereWeak), and a second
   * peak of the search widens the match's covariance; says how many directions were weak and
   * how many of them the prediction decided. */
  void decideAmbiguity(ScanMatch& m, const PreparedScan& scan, const Predicted& predicted, TrackingStep& step) const;
  /** Remembers the scan's motion (`rel`, its vehicle pose relative to the last keyframe; `raw`
   * the match before the prediction decided its weak directions). */
  void advance(const mrpt::poses::CPose2D& rel, const plicp::MatchResult& raw, const Predicted& predicted);
  /** Whether the scan at `rel` makes a node: past the keyframe threshold, and matched unless
   * more scans in a row went unmatched than one odd scan explains. */
  bool makesNode(const mrpt::poses::CPose2D& rel, bool matched);
  /** Makes the scan a node at step.pose, with its consecutive and dense edges. */
  void addNode(const PreparedScan& scan, TrackingStep& step);
  Keyframe& addKeyframe(const PreparedScan& scan, const mrpt::poses::CPose2D& pose);
  /** The rays of the last submap_keyframes keyframes in the last keyframe's sensor frame. */
  std::vector<correlative::Ray> submapRays() const;

  TrackingParams tracking_;
  plicp::PlicpParams plicp_;
  correlative::CorrelativeParams correlative_;
  ScanForms forms_;
  ScanMatcher matcher_;
  std::vector<Keyframe> keyframes_;
  std::unique_ptr<Submap> submap_;  ///< ending at the last keyframe
  mrpt::poses::CPose2D relative_;     ///< last scan's vehicle pose relative to the last keyframe
  mrpt::poses::CPose2D last_motion_;  ///< vehicle motion between the last two scans
  mrpt::Clock::time_point last_time_;  ///< the last scan's timestamp
  double last_interval_ = 0;           ///< [s] between the last two scans (0: unknown)
  size_t unmatched_in_a_row_ = 0;      ///< scans in a row without a match (tracked by the prediction)
  bool motion_matched_ = false;        ///< some scan's motion was matched: the prediction is measured
  SteadyMotion steady_;  ///< the recent motions, for the search's steady-motion prior
};

}  // namespace swslam::tracking

#pragma once
// Local tracking (paper sec. II.C, Fig. 1-2): each scan is matched by PLICP against the
// latest keyframe, starting from the previous relative pose moved by the expected motion.
// Past a translation or rotation threshold a new keyframe (graph node) is made; it is
// connected to the previous node and, densely, to every node within a radius.

#include <swslam/correlative/params.h>
#include <swslam/correlative/score_grid.h>
#include <swslam/graph/constraint.h>
#include <swslam/plicp/plicp.h>
#include <swslam/tracking/ambiguity.h>
#include <swslam/tracking/params.h>
#include <swslam/tracking/steady_motion.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

namespace swslam::tracking
{
/** A graph node made by tracking: its vehicle pose and the scan other scans match against. */
struct Keyframe
{
  size_t id = 0;
  mrpt::poses::CPose2D pose;  ///< vehicle pose in the map frame (updated by the optimizer)
  std::shared_ptr<const plicp::ReferenceScan> scan;
  std::shared_ptr<const FacingNormals> facing;  ///< of scan's points (tracking/ambiguity.h)
  mrpt::poses::CPose2D sensor_pose;  ///< sensor mounting on the vehicle
  mrpt::Clock::time_point timestamp;
};

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
  plicp::MatchResult match;  ///< the match against the keyframe or local map, in the keyframe's sensor frame (status says if it failed)
  TrackingSource source = TrackingSource::First;
  bool new_keyframe = false;
  std::vector<graph::Constraint> edges;  ///< the new node's edges
  size_t dense_matches = 0;        ///< dense-neighbour matches tried for the new node
  bool searched = false;           ///< the correlative search ran (source says if it won)
  double match_time = 0;           ///< [s] spent matching against the keyframe (search included)
  size_t valid_rays = 0;           ///< valid rays of this scan
  bool two_peaks = false;  ///< the search found a second pose, far from the kept one, of similar score...
  Eigen::Vector3d peak_offset = Eigen::Vector3d::Zero();  ///< ...this far from it (sensor frame [x, y, theta])
  /** the first and the searched match differed where the scans cannot tell them apart, and
   * the prediction chose (correlative::predictionChoice) */
  bool prediction_chose = false;
  /** Directions the scan could not decide: the kept match's weak ones, plus one for a second
   * peak of the search, plus one for a choice the prediction made (0: none) */
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

  /** Tracks one scan. `odometry_increment` is the vehicle motion since the previous scan, if
   * known. The observation's geometry must have passed sensor::checkObservationGeometry, as
   * every scan fed to SlamSystem has; a scan with few or no valid rays is tracked by the
   * fallback. */
  TrackingStep process(const mrpt::obs::CObservation2DRangeScan& obs,
                       const std::optional<mrpt::poses::CPose2D>& odometry_increment = std::nullopt);

  /** Moves a keyframe (after graph optimization); later scans are placed relative to it. */
  void setKeyframePose(size_t id, const mrpt::poses::CPose2D& pose);

  const std::vector<Keyframe>& keyframes() const { return keyframes_; }

 private:
  Keyframe& addKeyframe(const sensor::Scan& scan, const mrpt::poses::CPose2D& pose);
  std::optional<graph::Constraint> matchEdge(const Keyframe& from, const Keyframe& to, const sensor::Scan& scan,
                                       graph::EdgeKind kind) const;
  graph::Constraint priorEdge(const Keyframe& from, const Keyframe& to) const;
  bool pastKeyframeThreshold(const mrpt::poses::CPose2D& relative) const;
  /** How many of a match's directions were weak, and along how many of them the prior decided. */
  struct WeakDirections
  {
    int weak = 0, prior_decided = 0;
  };
  /** The weak directions of a converged match of `cur` against `ref`, given with their
   * FacingNormals (`cur_facing` nullptr: computed here if needed; tracking/ambiguity.h):
   * takes `prior` (sensor frame; translation variance prior_var_xy, rotation variance
   * lost_prior_sigma_theta^2) along those of them that are unobservable, and says how many
   * there were of each. */
  WeakDirections takePriorWhereWeak(plicp::MatchResult& m, const plicp::ReferenceScan& ref,
                                    const FacingNormals& ref_facing, const sensor::Scan& cur,
                                    const FacingNormals* cur_facing, const mrpt::poses::CPose2D& prior,
                                    double prior_var_xy, double length) const;
  /** After a search: the offset from the match of a second peak of the search's objective of
   * similar height, away from the match's own (correlative/peaks.h), if there is one. */
  std::optional<Eigen::Vector3d> secondPeakOffset(const sensor::Scan& scan, const mrpt::poses::CPose2D& guess,
                                                  const plicp::MatchResult& m) const;
  /** The match of `scan` from `guess` (the last keyframe's sensor frame) against the reference
   * (matchReference()), re-aligned by the correlative search when its prediction failed, or
   * when `measured_prediction` is false (the guess comes neither from odometry nor from a
   * motion matched before) and search_first_match is on. A match chosen after a search with
   * under searched_min_inlier_fraction of the scan's rays as inliers is returned failed. */
  plicp::MatchResult matchLast(const sensor::Scan& scan, const mrpt::poses::CPose2D& guess, bool measured_prediction,
                               TrackingStep& step);
  /** The match of `scan` from `guess`, both in the last keyframe's sensor frame, against the
   * last keyframe's scan. */
  plicp::MatchResult matchReference(const sensor::Scan& scan, const mrpt::poses::CPose2D& guess) const;
  /** The consecutive edge of a new node from `match` (of its scan, in `previous`'s sensor
   * frame). */
  graph::Constraint consecutiveEdge(const Keyframe& previous, const Keyframe& node,
                                    const plicp::MatchResult& match) const;
  /** Rays of the last submap_keyframes keyframes in the last keyframe's sensor frame. */
  std::vector<correlative::Ray> submapRays() const;

  TrackingParams tracking_;
  plicp::PlicpParams plicp_;
  correlative::CorrelativeParams correlative_;
  /** The score pyramid of the submap ending at the last keyframe, built the first time a scan
   * is searched against that keyframe. */
  std::shared_ptr<const correlative::ScorePyramid> search_pyramid_;
  size_t search_pyramid_keyframe_ = 0;
  std::vector<Keyframe> keyframes_;
  mrpt::poses::CPose2D relative_;     ///< last scan's vehicle pose relative to the last keyframe
  mrpt::poses::CPose2D last_motion_;  ///< vehicle motion between the last two scans
  mrpt::Clock::time_point last_time_;  ///< the last scan's timestamp
  double last_interval_ = 0;           ///< [s] between the last two scans (0: unknown)
  size_t confirmed_in_a_row_ = 0;      ///< scans in a row whose match confirmed the prediction
  size_t unmatched_in_a_row_ = 0;      ///< scans in a row without a match (tracked by the prediction)
  bool motion_matched_ = false;        ///< some scan's motion was matched: the prediction is measured
  SteadyMotion steady_;  ///< the recent motions, for the search's steady-motion prior
};

}  // namespace swslam::tracking

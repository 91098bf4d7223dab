#pragma once
// One localization run on a saved map (doc/localization.md), whatever feeds it: a log
// (swslam-localize) or a live sensor (swslam-live --localize). It holds the map's nodes, the
// whole-map search and the localizer, localizes each scan fed to it, keeps one row per scan,
// counts the rays of the scans it placed by a match for the change report, and writes the
// run's outputs: localization.tum, localization.csv, summary.md, changes.md and changes.png.

#include <swslam/app/config.h>
#include <swslam/app/saved_map.h>
#include <swslam/localize/localizer.h>
#include <swslam/map/change_detection.h>
#include <swslam/map/outputs.h>
#include <swslam/sensor/scan_input.h>
#include <swslam/system/input_gate.h>

#include <mrpt/poses/CPose2D.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace swslam::app
{
class LocalizationSession
{
 public:
  /** Localizes on `saved` (read with readSavedMap from `map_dir`) with `config`; from
   * `initial_pose` if given, else by relocalization. Throws std::invalid_argument naming a
   * node whose scan fails the input's geometry check, or a map with no occupied cell. */
  LocalizationSession(const SavedMap& saved, const std::string& map_dir, const Config& config,
                      const std::optional<mrpt::poses::CPose2D>& initial_pose);
  ~LocalizationSession();

  /** Localizes one scan after the input gate the SLAM system applies (system/input_gate.h: its
   * geometry, a stamp out of range or not after the last, unusable odometry dropped); a scan
   * the gate skips is counted, and null returned with the gate's result in `refused`. Throws
   * what the localizer throws (a module failure). */
  const localize::LocalizedScan* feed(sensor::ScanInput in, system::FeedResult* refused = nullptr);

  size_t scans() const { return rows_.size(); }
  bool anyLocalized() const;
  /** The state of the last scan (lost before the first). */
  localize::LocalizationState lastState() const;

  /** Where the scans placed so far contradict the map (doc/sessions.md, What changed). */
  map::ChangeReport changes() const;

  /** summary.md's text (without its title), for `input`. */
  std::string summary(const std::string& input) const;
  /** Writes the outputs into `dir`, each atomically; the ones that failed. */
  std::vector<map::OutputProblem> write(const std::string& dir, const std::string& input) const;
  static const std::vector<std::string>& outputFiles();

 private:
  struct Row
  {
    double t = 0;
    localize::LocalizedScan scan;
    double ms = 0;  ///< processing time
  };
  std::string map_line_;  ///< the map, described
  std::unique_ptr<localize::MapNodes> nodes_;
  std::unique_ptr<localize::Relocalizer> relocalizer_;
  std::unique_ptr<localize::Localizer> localizer_;
  mrpt::maps::COccupancyGridMap2D grid_;  ///< the map's grid, under the change picture
  /** The map nodes' rays, and those of the scans placed by a match, one at least
   * [tracking] keyframe_translation or keyframe_rotation from the last one counted. */
  map::SurveyEvidence before_, after_;
  std::optional<mrpt::poses::CPose2D> last_counted_;
  double keyframe_translation_ = 0, keyframe_rotation_ = 0;
  std::vector<mrpt::poses::CPose2D> counted_poses_;
  system::InputGate gate_;
  std::vector<Row> rows_;
  size_t skipped_ = 0;
};

}  // namespace swslam::app

#pragma once
// A run's files, written into one directory, each atomically: trajectory.tum (every scan),
// keyframes.tum, graph.graph (MRPT format), stats.csv, summary.md (Table I), run.ini (how the
// run was made: run_record.h), and the map
// outputs of writeMapOutputs (map.gridmap.gz, map.png, map.yaml + map.pgm, map.bt,
// render.png).

#include <swslam/map/change_detection.h>
#include <swslam/map/outputs.h>
#include <swslam/system/slam_system.h>

#include <string>
#include <vector>

namespace swslam::app
{
/** Writes every output; one that fails does not stop the others (the failures are
 * returned). Throws std::invalid_argument if `dir` cannot be created. */
std::vector<map::OutputProblem> writeRunOutputs(const std::string& dir, const system::RunResults& results,
                                           const mrpt::maps::COccupancyGridMap2D& grid,
                                           const map::MapParams& map_params, const std::string& summary,
                                           const std::string& run_record, bool render = true);

/** The change report's files (doc/sessions.md, What changed). */
inline constexpr const char* kChangeTable = "changes.md";
inline constexpr const char* kChangePicture = "changes.png";

/** A resumed or localized run's change report (doc/sessions.md): changes.md and changes.png
 * into `dir`; a file that cannot be written is added to `problems`. */
void writeChangeOutputs(const std::string& dir, const mrpt::maps::COccupancyGridMap2D& grid, const map::Overlay& overlay,
                        const map::ChangeReport& changes, std::vector<map::OutputProblem>& problems);

/** The files writeRunOutputs and writeChangeOutputs write (render.png and the change report
 * included), by name. */
std::vector<std::string> runOutputFiles();

/** The run's last line: "# outputs in DIR/ (map.png, render.png, trajectory.tum, stats.csv,
 * summary.md)", naming only those of them that are in `dir`, and "; not written: ..." every
 * output (of runOutputFiles, render.png only if `render`, the change report never: only a
 * resumed run writes it) that is not. */
std::string outputsLine(const std::string& dir, bool render);

/** Table I figures of a run; with a ground truth, also ATE and RPE (poses associated within
 * `max_dt` seconds). Throws std::runtime_error if the ground truth does not overlap. */
system::RunSummary summarizeRun(const system::RunResults& results, double wall_time,
                        const std::vector<common::StampedPose>* ground_truth = nullptr, double max_dt = 0.01);

/** What the map pictures draw: the every-scan trajectory (the scans the prediction placed, by
 * fallback or along a direction their match could not decide, marked), the nodes and every
 * graph edge by kind, those in `results.switched_off` marked. */
map::Overlay overlayOf(const system::RunResults& results);

}  // namespace swslam::app

#pragma once
// A saved session (doc/sessions.md): everything `swslam --resume` needs to continue mapping,
// written as one folder that appears whole or not at all.
//
//   session.ini     [session] format (kSessionFormat), nodes, version
//   run.ini         how the session's run was made (run_record.h); its configuration is the
//                   resumed run's
//   graph.graph     the pose graph with each edge's information, kind and switched-off mark
//                   (graph/io.h; MRPT reads it)
//   keyframes.tum   the nodes' stamps and optimized poses, node i on line i
//   nodes.rawlog    each node's observation, in node order (MRPT rawlog: RawLogViewer opens it)
//   map.gridmap.gz  the map (MRPT), for viewing; a resumed run maps the nodes again at their
//                   optimized poses

#include <swslam/app/run_record.h>
#include <swslam/io/scan_source.h>
#include <swslam/system/slam_system.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <functional>
#include <string>
#include <vector>

namespace swslam::app
{
/** 2: graph.graph may merge nodes into others ("kind=merged"); a format-1 session has none
 * and is read as it is. */
inline constexpr int kSessionFormat = 2;

struct Session
{
  RunRecord record;                  ///< the saved run's run.ini
  system::ResumedSession resumed;    ///< graph and node observations
  std::vector<double> node_times;    ///< keyframes.tum's stamps
};

/** Writes a session of `results` (its graph and keyframes) to `dir`: into a sibling folder
 * first, which then replaces `dir` (a previous session there stays until the new one is
 * whole). `observations[id]` is node id's observation. Throws std::runtime_error naming the
 * file that could not be written (`dir` is then as it was) or std::invalid_argument if the
 * observations do not fit the graph. */
void writeSession(const std::string& dir, const RunRecord& record, const system::RunResults& results,
                  const mrpt::maps::COccupancyGridMap2D& grid,
                  const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& observations);

/** Reads the session in `dir`. Throws std::invalid_argument naming the file and the problem:
 * a missing file, another format version, a graph line that does not parse, counts that
 * disagree (graph nodes, keyframes, observations), an observation whose stamp is not its
 * node's. */
Session readSession(const std::string& dir);

/** Calls visit(id, observation) for each node id in [first, times.size()) with the scan of
 * `log` (opened with `scans`, odometry not read) stamped times[id], in one pass: the nodes are
 * in time order. Throws std::runtime_error naming the first node whose scan the log does not
 * hold (`what` starts the message). */
void visitNodeScans(const std::vector<double>& times, size_t first, const std::string& log,
                    const io::ScanSourceOptions& scans, const io::CarmenParams& carmen, const std::string& what,
                    const std::function<void(size_t, const mrpt::obs::CObservation2DRangeScan::Ptr&)>& visit);

/** The observations of the nodes stamped `times[first..]`, taken from `log` (opened as the
 * run opened it) in one pass: the scan with each node's stamp, in order. Throws
 * std::runtime_error naming the first node whose scan the log does not hold. */
std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> nodeObservationsFromLog(const std::vector<double>& times,
                                                                           size_t first, const std::string& log,
                                                                           const RunRecord& how);

}  // namespace swslam::app

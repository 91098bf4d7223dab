#pragma once
// The `swslam-regen-map` program: a finished run's map rebuilt from its graph and the input log
// (regen_map.h), e.g. at 0.1 m for the offline map, and written as a run writes its map files
// (doc/system.md). The options are plain values: the program's executable fills them without
// loading the library.

#include <iosfwd>
#include <optional>
#include <string>

namespace swslam::app
{
struct RegenMapOptions
{
  std::string run;     ///< output directory of a swslam run (graph.graph, keyframes.tum)
  std::string input;   ///< the run's input log; empty: the one its run.ini names
  std::string output;  ///< where to write the map files
  std::string config;  ///< .ini ([map], [carmen]); empty: the run's run.ini, else the installed config/default.ini
  std::optional<double> resolution;  ///< [m] cell size; none: the config's
  bool render = true;  ///< render.png
};

/** Runs; prints the summary line to `out`, problems to `err`. Returns 0, 1 for bad options or
 * inputs (nothing written), 4 if a map file could not be written. */
int runRegenMap(const RegenMapOptions& opts, std::ostream& out, std::ostream& err);

}  // namespace swslam::app

#pragma once
// The `swslam-bench-localize` program: localization on a saved map scored against the
// reference poses of the localized log (doc/localization.md, Figures). The whole log from its
// first scan, relocalization from random starts, and a log of another place that must stay
// lost. The options are plain values: the executable fills them without loading the library.

#include <cstddef>
#include <iosfwd>
#include <string>

namespace swslam::app
{
struct BenchLocalizeOptions
{
  std::string map;        ///< a saved session or a swslam run folder
  std::string map_truth;  ///< TUM reference poses of the map's run: the map frame to the world
  std::string input;      ///< the log localized
  std::string truth;      ///< its TUM reference poses (a pose per scan, by stamp)
  std::string elsewhere;  ///< a log of another place (empty: not run)
  size_t starts = 100;    ///< random starts (0: none)
  unsigned seed = 1;
  double window = 2.0;    ///< [s] of log a start has to relocalize in
  double follow = 5.0;    ///< [s] of log tracked after a relocalization, scored
  double max_error = 0.05;  ///< [m] a relocalization this close to the reference succeeds
  bool use_odometry = true;
};

/** Runs; prints the figures to `out`. Exit codes as app/exit_codes.h. */
int runBenchLocalize(const BenchLocalizeOptions& opts, std::ostream& out, std::ostream& err);

}  // namespace swslam::app

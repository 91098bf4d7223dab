#pragma once
// The `swslam-bench-map` program: map construction timed on a log with reference poses
// (bench/map_builder.h), the map of the result optionally written as a run writes its map. The
// options are plain values: the program's executable fills them without loading the library.

#include <cstddef>
#include <iosfwd>
#include <string>

namespace swslam::app
{
struct BenchMapOptions
{
  std::string input;         ///< rawlog with 2D scans
  std::string ground_truth;  ///< reference poses (TUM)
  std::string config;        ///< .ini ([map]); empty: [map]'s defaults
  std::string output;        ///< write the map outputs here; empty: none
  size_t node_every = 20;    ///< one node every this many scans
};

/** Runs; prints the figures to `out`, problems to `err`. Returns 0, or 1 for bad options or
 * inputs (a map file that could not be written is only printed). */
int runBenchMap(const BenchMapOptions& opts, std::ostream& out, std::ostream& err);

}  // namespace swslam::app

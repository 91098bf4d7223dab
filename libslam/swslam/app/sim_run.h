#pragma once
// The `swslam-sim` program: a simulated dataset (rawlog, ground truth, world picture) from a
// scenario file (sim/simulator.h, doc/simulator.md). The options are plain values: the
// program's executable fills them without loading the library.

#include <iosfwd>
#include <string>

namespace swslam::app
{
struct SimOptions
{
  std::string scenario;  ///< scenario .ini
  std::string output;    ///< output directory (created if missing)
  bool summary = true;   ///< print the summary
};

/** Runs; prints the summary to `out`. Returns 0, or 1 after printing the problem to `err`. */
int runSim(const SimOptions& opts, std::ostream& out, std::ostream& err);

}  // namespace swslam::app

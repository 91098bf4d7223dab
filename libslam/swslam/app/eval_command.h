#pragma once
// The `swslam-eval` application: trajectory accuracy against a reference (ATE and RPE, or the
// Kuemmerle relations metric), and, with no reference, how well the scans agree at a
// trajectory's poses and how far their own constraints pull it (doc/evaluation.md).

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace swslam::app
{
struct EvalOptions
{
  std::string command;    ///< ate | relations | consistency | laser-optimum
  std::string estimate;   ///< the trajectory evaluated (TUM)
  std::string reference;  ///< ground truth (TUM), relations file, or the log (rawlog or CARMEN)
  std::string config;     ///< consistency, laser-optimum: the run's .ini
  std::string sensor_label;  ///< consistency, laser-optimum: empty: the first sensor seen
  std::string output;     ///< laser-optimum: write the optimum here (TUM); empty: nowhere
  std::vector<std::string> compare;  ///< consistency: more trajectories scored on the same pairs
  double max_dt = 0.01;   ///< [s] timestamp association tolerance
  double segment = 1.0;   ///< [m] RPE segment length along the ground truth
  std::optional<double> radius;  ///< [m] consistency: default 3; laser-optimum: [tracking] dense_radius
  long min_gap = 1;       ///< consistency: pairs at least this many scored scans apart
  long revisit_gap = 30;  ///< consistency: pairs this many scored scans apart are revisits
  long stride = 1;        ///< consistency, laser-optimum: every K-th scan
};

/** The commands, in the order the help lists them (inline: the program's executable parses
 * its command line with them before it loads the library). */
inline std::vector<std::string> evalCommands() { return {"ate", "relations", "consistency", "laser-optimum"}; }

/** Runs one command and prints its report to `out`, its warnings to `err` (ate: part of the
 * estimate not matched by stamp). Throws std::invalid_argument naming the
 * option that is wrong, std::runtime_error naming an input that cannot be used. */
void runEval(const EvalOptions& opts, std::ostream& out, std::ostream& err);

}  // namespace swslam::app

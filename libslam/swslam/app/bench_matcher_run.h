#pragma once
// The `swslam-bench-matcher` program: PLICP, PLICP with tracking's search rules, and MRPT's
// CICP timed on scan pairs of a log with reference poses (bench/matcher.h). The options are
// plain values: the program's executable fills them without loading the library.

#include <cstddef>
#include <iosfwd>
#include <string>

namespace swslam::app
{
struct BenchMatcherOptions
{
  std::string input;         ///< rawlog with 2D scans
  std::string ground_truth;  ///< reference poses (TUM)
  std::string config;        ///< .ini ([plicp], [correlative], [tracking]); empty: their defaults
  std::string method;        ///< only this matcher (plicp, plicp+search, cicp-classic, cicp-lm); empty: all
  size_t stride = 1;         ///< pair scans k and k + stride
  bool floor = false;        ///< also time the work before a match's first step, and a search's parts
  bool misses = false;       ///< also count and explain plicp+search's pairs 5 cm or more off
};

/** Runs; prints the rows to `out`. Returns 0, or 1 after printing the problem to `err` for bad
 * options or inputs. */
int runBenchMatcher(const BenchMatcherOptions& opts, std::ostream& out, std::ostream& err);

}  // namespace swslam::app

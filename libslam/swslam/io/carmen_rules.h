#pragma once
// The two data rules of the CARMEN converter (see doc/carmen.md):
// - saturation: in these logs "no return" is a reading at the sensor maximum, which shows
//   as a pile of readings just below the largest value of the log;
// - timestamps: each stream must be strictly increasing; problems are detected, counted
//   and optionally repaired.

#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <optional>
#include <vector>

namespace swslam::io
{
/** Finds the saturation value of one laser from all its readings, in one streaming pass.
 * With m the largest finite positive reading, the cluster is the readings in
 * [m * (1 - rel_tol), m]. If it holds at least `min_count` readings, the laser saturates
 * and threshold() is the smallest reading of the cluster: readings >= it are "no return".
 * Otherwise a few glitches may sit above the pile (one 500 m reading over a log's 81.91 m
 * "no return" rays): the highest band of readings (two bins of relative width rel_tol) that
 * holds at least `min_count` readings and at least three times as many as the band below it
 * (a spike, not the tail of the ranges), with fewer than `min_count` readings above it, is the
 * pile, and the readings above it are glitches (glitchesAbove()). */
class SaturationDetector
{
 public:
  SaturationDetector(double rel_tol, size_t min_count);
  void add(double range);  ///< non-finite and non-positive readings are ignored
  std::optional<double> threshold() const;
  double largest() const { return max_; }
  size_t clusterSize() const;
  /** Readings above the pile threshold() found below the largest reading (0 if none). */
  size_t glitchesAbove() const;

 private:
  struct Bin
  {
    size_t count = 0;
    double min = 0;
  };
  void prune();
  /** The pile below glitches: its smallest reading and the readings above it. */
  std::optional<std::pair<double, size_t>> pileBelowGlitches() const;
  double rel_tol_;
  size_t min_count_;
  double max_ = 0;
  std::vector<double> near_top_;  ///< readings that were within rel_tol of the max when added
  size_t pruned_size_ = 0;
  std::map<int64_t, Bin> bins_;   ///< every reading, by floor(log(range) / log(1 + rel_tol))
};

/** Median of the positive differences of consecutive values not larger than `max_gap`;
 * `fallback` if there is none. */
double medianPositivePeriod(const std::vector<double>& times, double max_gap, double fallback);

/** What happened to one timestamp of a stream. */
enum class TimestampIssue
{
  None,
  NonIncreasing,  ///< t <= previous timestamp of the stream
  ForwardJump     ///< t - previous > max_gap (e.g. a 2^32 overflow)
};

/** Checks one stream of timestamps (one sensor) in order, and repairs it if asked: a bad
 * timestamp becomes previous + period, so the stream is strictly increasing. "Previous" is
 * the previous timestamp as output (repaired or not). The first timestamp is always kept. */
class TimestampSequence
{
 public:
  TimestampSequence(double period, double max_gap, bool repair)
      : period_(period), max_gap_(max_gap), repair_(repair)
  {
  }
  /** Returns the timestamp to use for `t`; `issue` says what was wrong with it. */
  double next(double t, TimestampIssue& issue);

 private:
  double period_, max_gap_;
  bool repair_;
  bool started_ = false;
  double prev_ = 0;
};

}  // namespace swslam::io

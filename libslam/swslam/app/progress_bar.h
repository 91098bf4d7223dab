#pragma once
// A one-line progress bar with scans/s and ETA, redrawn at most a few times per second, only
// when the stream is a terminal.

#include <chrono>
#include <cstdio>
#include <string>

namespace swslam::app
{
class ProgressBar
{
 public:
  /** `enabled` false: draws nothing (e.g. output redirected to a file). */
  ProgressBar(std::FILE* out, bool enabled);
  /** `fraction` of the input done, `scans` processed so far, `extra` appended (e.g. nodes). */
  void update(double fraction, size_t scans, const std::string& extra = {});
  /** True if update() would draw now (so callers can skip gathering its figures). */
  bool due() const;
  /** Clears the line. */
  void done();

  /** The bar's text (pure: for tests). */
  static std::string format(double fraction, size_t scans, double elapsed_s, const std::string& extra);

 private:
  std::FILE* out_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_draw_;
  bool drawn_ = false;
};

/** True if `f` is a terminal. */
bool isTerminal(std::FILE* f);

}  // namespace swslam::app

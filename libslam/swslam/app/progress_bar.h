#pragma once
// Progress with scans/s and ETA: on a terminal a one-line bar redrawn at most a few times per
// second; elsewhere (a log file, CI) a plain line at every tenth of the input.

#include <chrono>
#include <cstdio>
#include <string>

namespace swslam::app
{
enum class ProgressStyle
{
  Off,
  Bar,    ///< redrawn in place (a terminal)
  Lines,  ///< a line at every tenth (not a terminal)
};

class ProgressBar
{
 public:
  /** `enabled` false: draws nothing. */
  ProgressBar(std::FILE* out, bool enabled);
  /** `prefix` starts each plain line (e.g. "swslam: "). */
  ProgressBar(std::FILE* out, ProgressStyle style, std::string prefix = {});
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
  ProgressStyle style_;
  std::string prefix_;
  int tenths_shown_ = 0;  ///< Lines: the last tenth printed
  std::chrono::steady_clock::time_point start_, last_draw_;
  bool drawn_ = false;
};

/** True if `f` is a terminal. */
bool isTerminal(std::FILE* f);

/** Bar on a terminal, Lines elsewhere; Off if `wanted` is false. */
ProgressStyle progressStyleFor(std::FILE* f, bool wanted);

}  // namespace swslam::app

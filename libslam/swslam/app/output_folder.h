#pragma once
// A run's output folder, held for the run: created if missing and checked writable before any
// work, locked against a second run writing into it at the same time, and cleared of the
// temporary files a killed run left. Just before a run writes its outputs, the previous run's
// outputs are removed, so that the folder never holds a mix of two runs.

#include <string>
#include <vector>

namespace swslam::app
{
class OutputFolder
{
 public:
  /** Throws std::invalid_argument naming the folder and the problem: it cannot be created or
   * written, or another run holds it (its lock, `.swslam.lock`, is released when that
   * process ends, however it ends). */
  explicit OutputFolder(const std::string& dir);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::string& path() const { return dir_; }

  /** Removes the files of `names` that a previous run left (once: later calls do nothing,
   * the files are this run's). */
  void clearPreviousRun(const std::vector<std::string>& names);

  /** Temporary files removed when the folder was taken (left by a killed run). */
  size_t staleRemoved() const { return stale_removed_; }

 private:
  std::string dir_;
  int lock_fd_ = -1;
  bool cleared_ = false;
  size_t stale_removed_ = 0;
};

}  // namespace swslam::app

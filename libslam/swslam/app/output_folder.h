#pragma once
// A run's output folder, held for the run: created if missing and checked writable before any
// work, locked against a second run writing into it at the same time, and cleared of the
// temporary files a killed run left. A run's outputs replace the previous run's as one
// (replaceRun), so that the folder never holds a mix of two runs and a run that could not
// write all of its outputs does not destroy the previous run's.

#include <swslam/map/outputs.h>

#include <functional>
#include <string>
#include <vector>

namespace swslam::app
{
class OutputFolder
{
 public:
  /** Throws std::invalid_argument naming the folder and the problem: it cannot be created or
   * written, its lock file is no file (a directory, a FIFO: named), or another run holds it
   * (its lock, `.swslam.lock`, is released when that process ends, however it ends). */
  explicit OutputFolder(const std::string& dir);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::string& path() const { return dir_; }

  /** Removes the files of `names` that a previous run left (once: later calls do nothing,
   * the files are this run's). */
  void clearPreviousRun(const std::vector<std::string>& names);

  /** The lock file in the folder (a file: anything else there is an error naming it). */
  static constexpr const char* kLockFile = ".swslam.lock";

  /** Where replaceRun leaves a run's outputs that could not all be written while the folder
   * holds a previous run's. */
  static constexpr const char* kUnfinished = "unfinished-run";

  /** What replaceRun did. */
  struct Replaced
  {
    std::vector<map::OutputProblem> problems;  ///< the outputs `write` could not write
    /** The previous run's outputs were kept, and this run's are in kUnfinished (some failed
     * while the folder held the previous run's). */
    bool kept_previous = false;
  };

  /** Writes a run's outputs (files named among `names`) as one: `write` writes them into a
   * staging folder inside this one and returns the outputs it could not write. If it wrote
   * them all, or the folder holds none of `names`, they replace the previous run's: each file
   * renamed into the folder, the previous run's files of `names` it did not write removed, and
   * a kUnfinished folder left by an earlier failure removed. Otherwise the previous run's
   * outputs stay as they were and this run's go to kUnfinished (replacing an older one). Throws
   * std::runtime_error naming the folder if the staging folder cannot be made or emptied. */
  Replaced replaceRun(const std::vector<std::string>& names,
                      const std::function<std::vector<map::OutputProblem>(const std::string& dir)>& write);

  /** Temporary files removed when the folder was taken (left by a killed run). */
  size_t staleRemoved() const { return stale_removed_; }

 private:
  std::string dir_;
  int lock_fd_ = -1;
  bool cleared_ = false;
  size_t stale_removed_ = 0;
};

}  // namespace swslam::app

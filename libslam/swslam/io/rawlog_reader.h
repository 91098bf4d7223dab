#pragma once
// Streaming reader of MRPT rawlogs in both formats (observation-only, and
// action/sensory-frame pairs). Reads one entry at a time; never loads the whole file.

#include <swslam/io/read_progress.h>

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation.h>

#include <deque>
#include <memory>
#include <stdexcept>
#include <string>

namespace mrpt::serialization
{
class CArchive;
}

namespace swslam::io
{
/** Thrown when a rawlog is corrupt or truncated. Everything returned before it stays valid. */
class RawlogError : public std::runtime_error
{
 public:
  RawlogError(const std::string& msg, size_t entry) : std::runtime_error(msg), entry_(entry) {}
  /** Index of the rawlog entry that could not be read (0-based). */
  size_t entry() const { return entry_; }

 private:
  size_t entry_;
};

/** One item of a rawlog, in file order: an observation, or an odometry increment
 * from an action (rawlogs in action/sensory-frame format). Exactly one is set. */
struct RawlogItem
{
  mrpt::obs::CObservation::Ptr observation;
  mrpt::obs::CActionRobotMovement2D::Ptr odometry_increment;
};

class RawlogReader
{
 public:
  /** Opens a rawlog (plain or gzip). Throws std::runtime_error if it cannot be opened. */
  explicit RawlogReader(const std::string& path);
  ~RawlogReader();

  /** Reads the next item. Returns false at the clean end of the file.
   * Throws RawlogError (with the entry index) on corrupt or truncated data, and on a scan
   * entry whose ray count is above 2^20 (checked before MRPT allocates for it). */
  bool next(RawlogItem& item);

  /** Number of top-level rawlog entries read so far. */
  size_t entriesRead() const { return entries_; }
  /** Fraction of the file read so far, in [0, 1] (for progress and ETA). */
  double fractionRead() const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  mrpt::io::CFileGZInputStream file_;
  ReadProgress progress_;
  class LookaheadArchive;
  std::unique_ptr<LookaheadArchive> archive_;
  std::deque<RawlogItem> pending_;  ///< items of an already-read sensory frame / action set
  size_t entries_ = 0;
};

}  // namespace swslam::io

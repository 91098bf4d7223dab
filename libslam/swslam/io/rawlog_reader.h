#pragma once
// Streaming reader of MRPT rawlogs in both formats (observation-only, and
// action/sensory-frame pairs). Reads one entry at a time; never loads the whole file.
//
// MRPT's deserializers trust every count and length in the file: a damaged entry crashed
// them or made them allocate tens of gigabytes. So the entries are decoded in a child process
// (io/sandboxed_decoder.h) under a memory budget (kDecoderMemoryBudget), which sends each item
// re-serialized; a crash, an exhausted budget or a stall (kDecoderStallTimeout) there is a
// RawlogError here, naming the entry.
// Construct readers before the process starts threads (the child is a fork).

#include <swslam/io/sandboxed_decoder.h>

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation.h>

#include <memory>
#include <stdexcept>
#include <string>

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
  /** Opens a rawlog (plain or gzip) and starts its decoder process. Throws
   * std::runtime_error if it cannot be opened. */
  explicit RawlogReader(const std::string& path);
  ~RawlogReader();

  /** Reads the next item. Returns false at the clean end of the file.
   * Throws RawlogError (with the entry index and byte offset in its message) on corrupt or
   * truncated data, on a scan entry whose ray count is above 2^20 (checked before MRPT
   * allocates for it), on an entry that crashes MRPT's decoder or needs more than the
   * decoder's memory budget, on a scan past the bounds of sensor/input_bounds.h (its rays, its
   * sensor's mounting); and again on every call after that. */
  bool next(RawlogItem& item);

  /** Number of top-level rawlog entries read so far. */
  size_t entriesRead() const { return entries_; }
  /** Fraction of the file read so far, in [0, 1] (for progress and ETA). */
  double fractionRead() const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::unique_ptr<SandboxedDecoder> decoder_;
  DecodedFrame frame_;  ///< the last frame read (its buffer is reused)
  size_t entries_ = 0;
  double fraction_ = 0;
  std::shared_ptr<RawlogError> refused_;  ///< a scan past the input bounds: the reading ends there
};

}  // namespace swslam::io

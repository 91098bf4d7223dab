#pragma once
// Where a scan enters the system (SlamSystem::feed): the checks it must pass, on the caller's
// thread, before any module sees it. A timestamp outside 1970-2200 or one further before the
// latest taken than a logger's jitter, and inconsistent geometry, skip the scan and say why; a
// stamp that repeats or steps back a little, right after one that went forward, is taken under
// its own stamp and said; a log
// whose stamp jumped forward resumes once enough scans behind it come in order; an odometry
// increment that is not finite, or longer than the vehicle can go, is dropped (the scan is
// tracked without it) and said.

#include <swslam/sensor/scan_input.h>
#include <swslam/system/options.h>

#include <cstddef>
#include <string>

namespace swslam::system
{
/** Why feed() did not take a scan. */
enum class FeedStatus
{
  Accepted,
  TimestampNotIncreasing,  ///< backwards or duplicated: skipped
  TimestampOutOfRange,     ///< not in 1970-2200 (common/unix_time.h), e.g. in microseconds: skipped
  BadGeometry,             ///< too few beams, aperture, max range or sensor pose unusable: skipped
  OdometryDropped,         ///< taken, without its odometry increment (not finite, or too long)
  TimestampsResumed,       ///< taken: the scans behind a stamp that jumped forward resume the log
  TimestampStepBack,       ///< taken: its stamp repeats the latest or is a little before it
  Stopped,                 ///< the pipeline stopped (finish() was called or a module failed)
};
/** The scan was taken (possibly without its odometry), not skipped. */
inline bool scanTaken(FeedStatus s)
{
  return s == FeedStatus::Accepted || s == FeedStatus::OdometryDropped || s == FeedStatus::TimestampsResumed ||
         s == FeedStatus::TimestampStepBack;
}

struct FeedResult
{
  FeedStatus status = FeedStatus::Accepted;
  std::string message;  ///< what was wrong: why a scan was skipped, or what of it was dropped
  /** The scan was taken (possibly without its odometry). */
  bool ok() const { return scanTaken(status); }
};

class InputGate
{
 public:
  /** Reads timestamp_resume_scans, timestamp_step_back and max_odometry_speed. */
  explicit InputGate(const SystemOptions& options) : options_(options) {}

  /** Checks `input`, dropping its odometry increment if that is unusable; the result says
   * whether the scan is taken (never Stopped). */
  FeedResult admit(sensor::ScanInput& input);

 private:
  SystemOptions options_;
  double last_timestamp_ = -1;  ///< the latest stamp taken
  bool last_went_forward_ = false;  ///< the last scan taken had a stamp after the one before it
  size_t behind_in_order_ = 0;  ///< skipped scans in a row behind last_timestamp_, in order
  double last_behind_ = 0;      ///< the last of them's timestamp
};

}  // namespace swslam::system

#pragma once
// Records observations to an MRPT rawlog (observation-only format) as they arrive, flushing
// to the file at least every `flush_period`, so that a crash or power loss loses at most that
// much. The file is a plain (uncompressed) rawlog: MRPT tools and swslam read it as it is.

#include <mrpt/obs/CObservation.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <string>

namespace mrpt::serialization
{
class CArchive;
}

namespace swslam::io
{
class RawlogRecorder
{
 public:
  /** Creates (truncates) `path`; throws std::runtime_error naming it if it cannot. */
  RawlogRecorder(const std::string& path, std::chrono::milliseconds flush_period);
  ~RawlogRecorder();  ///< flushes

  /** Appends one observation; throws std::runtime_error if the write fails (disk full). */
  void write(const mrpt::obs::CObservation& obs);
  /** Pushes everything written so far to the operating system. */
  void flush();

  size_t written() const { return written_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::ofstream file_;
  std::unique_ptr<mrpt::serialization::CArchive> archive_;
  std::chrono::milliseconds flush_period_;
  std::chrono::steady_clock::time_point last_flush_;
  size_t written_ = 0;
};

}  // namespace swslam::io

#include <swslam/io/rawlog_recorder.h>

#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/archiveFrom_std_streams.h>

#include <stdexcept>

namespace swslam::io
{
RawlogRecorder::RawlogRecorder(const std::string& path, std::chrono::milliseconds flush_period)
    : path_(path),
      file_(path, std::ios::binary | std::ios::trunc),
      flush_period_(flush_period),
      last_flush_(std::chrono::steady_clock::now())
{
  if (!file_) throw std::runtime_error("recorder: cannot create '" + path + "'");
  archive_ = std::make_unique<mrpt::serialization::CArchiveStreamBase<std::ostream>>(file_);
}

RawlogRecorder::~RawlogRecorder()
{
  if (file_.is_open()) file_.flush();
}

void RawlogRecorder::write(const mrpt::obs::CObservation& obs)
{
  (*archive_) << obs;
  if (!file_) throw std::runtime_error("recorder: writing '" + path_ + "' failed (disk full?)");
  written_++;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_flush_ >= flush_period_)
  {
    flush();
    last_flush_ = now;
  }
}

void RawlogRecorder::flush()
{
  file_.flush();
  if (!file_) throw std::runtime_error("recorder: flushing '" + path_ + "' failed (disk full?)");
}

}  // namespace swslam::io

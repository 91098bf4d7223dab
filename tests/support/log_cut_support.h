#pragma once
// A part of a log, written as a rawlog of its scan observations: a map's part and the part
// localized on it or resumed from it.

#include <swslam/io/rawlog_recorder.h>
#include <swslam/io/scan_source.h>

#include <chrono>
#include <string>

namespace swslam::test
{
/** The scans [from, from + count) of `log` (odometry not read) written to `path`; returns `path`. */
inline std::string cutLog(const std::string& log, const std::string& path, size_t from, size_t count)
{
  auto source = io::openScanSource(log, io::ScanSourceOptions{false, "", "", ""}, io::CarmenParams());
  io::RawlogRecorder out(path, std::chrono::hours(1));
  sensor::ScanInput in;
  for (size_t k = 0; k < from + count && source->next(in); k++)
    if (k >= from) out.write(*in.observation);
  out.flush();
  return path;
}

/** lake-short's scans [from, from + count), as cutLog. */
inline std::string cutLakeShort(const std::string& path, size_t from, size_t count)
{
  return cutLog(std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.rawlog", path, from, count);
}

}  // namespace swslam::test

// Harness: io::CarmenLogReader over any bytes as a CARMEN log, read twice: with the default
// [carmen] parameters, and laser-only with timestamp repair. Documented error paths: a log
// whose timestamps are mostly out of range is refused (std::runtime_error saying so), a
// damaged gzip stream is a GzipError; otherwise malformed lines are skipped and counted. Promises
// checked: every record holds an observation with a finite timestamp >= 0 (negative ones
// are written as 0), which the observation holds; the statistics count every record returned.

#include "fuzz_input.h"

#include <swslam/io/carmen_log.h>
#include <swslam/io/gzip_file.h>

#include <cmath>
#include <memory>
#include <string>

namespace
{
void readAll(const std::string& path, const swslam::io::CarmenParams& params)
{
  using namespace swslam;
  size_t warnings = 0;
  std::unique_ptr<io::CarmenLogReader> opened;
  try
  {
    opened = std::make_unique<io::CarmenLogReader>(path, params, [&](const std::string&) { ++warnings; });
  }
  catch (const io::GzipError&)
  {
    return;
  }
  catch (const std::runtime_error& e)
  {
    // Refused as a whole: stamps, UTF-16 text, or a laser mounted beyond the bound by its PARAMs.
    const std::string what = e.what();
    SWSLAM_FUZZ_CHECK(what.find("timestamps are out of range") != std::string::npos ||
                          what.find("not the ASCII of a log") != std::string::npos ||
                          what.find("a sensor is mounted") != std::string::npos,
                      what);
    return;
  }
  io::CarmenLogReader& reader = *opened;
  io::CarmenRecord rec;
  size_t records = 0;
  while (true)
  {
    try
    {
      if (!reader.next(rec)) break;
    }
    catch (const io::GzipError&)
    {
      return;
    }
    ++records;
    SWSLAM_FUZZ_CHECK(rec.observation != nullptr, "line " + std::to_string(rec.line));
    SWSLAM_FUZZ_CHECK(std::isfinite(rec.timestamp) && rec.timestamp >= 0,
                      "line " + std::to_string(rec.line) + ": t = " + std::to_string(rec.timestamp));
    // The observation holds that time (MRPT's clock: 100 ns ticks in an int64 since 1601).
    const double held = mrpt::Clock::toDouble(rec.observation->timestamp);
    SWSLAM_FUZZ_CHECK(std::abs(held - rec.timestamp) <= 1e-3,
                      "line " + std::to_string(rec.line) + ": t = " + std::to_string(rec.timestamp) +
                          ", the observation holds " + std::to_string(held));
    const double f = reader.fractionRead();
    SWSLAM_FUZZ_CHECK(f >= 0 && f <= 1, "fractionRead() = " + std::to_string(f));
  }
  const auto& stats = reader.stats();
  SWSLAM_FUZZ_CHECK(records == stats.scans() + stats.odometry, io::formatCarmenStats(stats));
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam;
  const std::string path = fuzz::writeInput(data, size, "input.log");
  io::CarmenParams params;
  readAll(path, params);
  params.laser_only = params.repair_timestamps = true;
  readAll(path, params);
  return 0;
}

// Harness: io::carmen2rawlog over any bytes as a CARMEN log (laser only, repaired timestamps,
// reference odometry, ground truth written), then its outputs read back. Documented error
// paths (std::runtime_error naming the problem): "carmen2rawlog: no laser scan in ...", a log
// whose timestamps are mostly out of range, and a damaged gzip stream (io::GzipError, after
// the scans before the damage are written).
// Promises checked: the rawlog reads back without error, one observation per scan plus one
// reference odometry per reference pose; the TUM file reads back with one row per reference
// pose.

#include "fuzz_input.h"

#include <swslam/common/tum_io.h>
#include <swslam/io/carmen2rawlog.h>
#include <swslam/io/gzip_file.h>
#include <swslam/io/rawlog_reader.h>

#include <filesystem>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam;
  io::Carmen2RawlogOptions opts;
  opts.input = fuzz::writeInput(data, size, "input.log");
  opts.output = fuzz::scratchPath("output.rawlog");
  opts.ground_truth = fuzz::scratchPath("output.tum");
  opts.compress_level = 1;
  opts.reference_odometry = true;
  opts.params.laser_only = opts.params.repair_timestamps = true;
  std::filesystem::remove(opts.output);
  std::filesystem::remove(opts.ground_truth);
  io::CarmenStats stats;
  try
  {
    stats = io::carmen2rawlog(opts, [](const std::string&) {});
  }
  catch (const io::GzipError&)
  {
    return 0;  // what came before the damage is written, and said
  }
  catch (const std::runtime_error& e)
  {
    const std::string what = e.what();
    // common::writeAtomically prefixes "cannot write '<output>': " to the converter's reason.
    // Or a log refused as a whole: UTF-16 text, or a laser mounted beyond the bound by its PARAMs.
    SWSLAM_FUZZ_CHECK(what.find("carmen2rawlog: no laser scan in '") != std::string::npos ||
                          what.find("timestamps are out of range") != std::string::npos ||
                          what.find("not the ASCII of a log") != std::string::npos ||
                          what.find("a sensor is mounted") != std::string::npos,
                      what);
    SWSLAM_FUZZ_CHECK(!std::filesystem::exists(opts.output), "a failed conversion wrote " + opts.output);
    return 0;
  }
  const auto reference = common::readTum(opts.ground_truth);
  io::RawlogReader reader(opts.output);
  io::RawlogItem item;
  size_t observations = 0;
  while (reader.next(item))
  {
    SWSLAM_FUZZ_CHECK(item.observation != nullptr, "the converter writes observations only");
    ++observations;
  }
  SWSLAM_FUZZ_CHECK(observations == stats.scans() + reference.size(),
                    std::to_string(observations) + " observations read back, " +
                        std::to_string(stats.scans()) + " scans and " +
                        std::to_string(reference.size()) + " reference poses written");
  return 0;
}

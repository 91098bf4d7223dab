// Harness: io::Ros2BagReader over any bytes as a single .mcap file: the MCAP record reader
// (chunks in zstd, lz4 or none), the CDR decoding of LaserScan, Odometry and TFMessage, and
// their conversion. Documented error paths: std::runtime_error from the constructor (not
// MCAP, a damaged record before any topic, a topic choice, a mounting beyond the bound), a
// BagError from next() (a damaged record or message). Promises checked: the error's message
// index is the count of messages read; every scan has at most sensor::kMaxScanRays rays;
// fractionRead() stays in [0, 1]. Seeds: the MCAP files tests/ros2/make-bags.mjs writes.

#include "fuzz_input.h"

#include <swslam/io/ros2_bag_reader.h>
#include <swslam/sensor/input_bounds.h>

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <memory>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam;
  const std::string path = fuzz::writeInput(data, size, "input.mcap");
  std::unique_ptr<io::Ros2BagReader> reader;
  try
  {
    reader = std::make_unique<io::Ros2BagReader>(path, io::BagReaderOptions{});
  }
  catch (const std::runtime_error&)
  {
    return 0;
  }
  mrpt::obs::CObservation::Ptr o;
  try
  {
    while (reader->next(o))
      if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o))
        SWSLAM_FUZZ_CHECK(s->getScanSize() <= sensor::kMaxScanRays, std::to_string(s->getScanSize()) + " rays");
  }
  catch (const io::BagError& e)
  {
    SWSLAM_FUZZ_CHECK(e.message() == reader->messagesRead(), e.what());
  }
  const double f = reader->fractionRead();
  SWSLAM_FUZZ_CHECK(f >= 0 && f <= 1, "fractionRead() = " + std::to_string(f));
  return 0;
}

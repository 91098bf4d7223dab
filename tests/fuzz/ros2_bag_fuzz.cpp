// Harness: io::Ros2BagReader over any bytes as a single .mcap file: the MCAP record reader
// (chunks in zstd, lz4 or none), the CDR decoding of LaserScan, Odometry and TFMessage, and
// their conversion. Documented error paths: std::runtime_error from the constructor (not
// MCAP, a damaged record before any topic, a topic choice, a mounting beyond the bound), a
// BagError from next() (a damaged record or message). Promises checked: bag_reader_fuzz.h.
// Seeds: the MCAP files tests/ros2/make-bags.mjs writes.

#include "bag_reader_fuzz.h"

#include <swslam/io/ros2_bag_reader.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  return swslam::fuzz::readBag<swslam::io::Ros2BagReader>(data, size, "input.mcap");
}

// Harness: io::BagReader over any bytes as a ROS 1 bag: the records checked before librosbag
// reads them (io/ros1_bag_layout.h: lengths, headers, the index, each chunk decompressed from
// none, bz2 or lz4 and its records), then librosbag's reading, the decoding of LaserScan,
// Odometry and TFMessage, and their conversion. Documented error paths: std::runtime_error
// from the constructor (not a bag, a damaged or truncated bag, a topic choice, a mounting
// beyond the bound), a BagError from next() (a damaged chunk or message). Promises checked:
// bag_reader_fuzz.h. Seeds: tests/fuzz/seeds/ros1_bag/, small bags swslam-rawlog2bag wrote
// (one per chunk compression).

#include "bag_reader_fuzz.h"

#include <rosbag/bag.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  return swslam::fuzz::readBag<swslam::io::BagReader>(data, size, "input.bag");
}

// Each rosbag::Bag loads librosbag's encryption plugins (pluginlib) and unloads them with the
// last one: loaded again for every input, their static initializers register exit handlers
// that stay, which libFuzzer takes for a leak and checks by scanning the heap after every
// input (25 inputs a second). One Bag kept for the process keeps them loaded.
extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  static rosbag::Bag keep_plugins_loaded;
  return 0;
}

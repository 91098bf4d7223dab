// Harness: the CDR decoders of the three ROS 2 messages (io/ros2_messages.h) over any bytes:
// the first byte picks the type (0 LaserScan, 1 Odometry, 2 TFMessage, modulo 3), the rest is
// the message. Documented error path: CdrError. Promises checked: a scan has at most
// sensor::kMaxScanRays rays; a message decoded, written again (ros2_messages.h) in either
// byte order and decoded, is written to the same bytes (nothing read is lost or invented).
// Seeds: the messages tests/ros2/make-bags.mjs writes, prefixed by their type byte.

#include "fuzz_input.h"

#include <swslam/io/cdr_reader.h>
#include <swslam/io/ros2_messages.h>
#include <swslam/sensor/input_bounds.h>

namespace
{
template <class M>
void roundTrip(const uint8_t* data, size_t size, M (*decode)(const uint8_t*, size_t),
               std::vector<uint8_t> (*encode)(const M&, bool))
{
  M m;
  try
  {
    m = decode(data, size);
  }
  catch (const swslam::io::CdrError&)
  {
    return;
  }
  for (bool big : {false, true})
  {
    const std::vector<uint8_t> once = encode(m, big);
    const std::vector<uint8_t> twice = encode(decode(once.data(), once.size()), big);
    SWSLAM_FUZZ_CHECK(once == twice, "a decoded message written again reads differently");
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam::io;
  if (size == 0) return 0;
  switch (data[0] % 3)
  {
    case 0:
      try
      {
        const auto m = laserScanFromCdr(data + 1, size - 1);
        SWSLAM_FUZZ_CHECK(m.ranges.size() <= swslam::sensor::kMaxScanRays, std::to_string(m.ranges.size()));
      }
      catch (const CdrError&)
      {
      }
      roundTrip<sensor_msgs::LaserScan>(data + 1, size - 1, laserScanFromCdr, laserScanCdr);
      break;
    case 1: roundTrip<nav_msgs::Odometry>(data + 1, size - 1, odometryFromCdr, odometryCdr); break;
    default: roundTrip<tf2_msgs::TFMessage>(data + 1, size - 1, tfMessageFromCdr, tfMessageCdr); break;
  }
  return 0;
}

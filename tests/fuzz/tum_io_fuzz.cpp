// Harness: common::readTum over any bytes as a TUM trajectory file, then the poses it read
// written (formatTum) and read again. Documented error path: std::runtime_error "tum: '<path>'
// line L: ...". Promises checked: what was read writes back into a file that reads without
// error, with as many poses and the same timestamps (to the written microsecond).

#include "rows_round_trip.h"

#include <swslam/common/tum_io.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam;
  fuzz::rowsRoundTrip(data, size, "tum", common::readTum, common::formatTum,
                      [](const common::StampedPose& a, const common::StampedPose& b) {
                        return fuzz::sameStamp(a.t, b.t);
                      });
  return 0;
}

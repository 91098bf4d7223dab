// Harness: io::RawlogReader over any bytes as a rawlog file (plain or gzip, read through zlib).
// Documented error path: RawlogError from next() (corrupt or truncated entry). Promises
// checked: every item has exactly one of observation / odometry increment; the error's entry
// index is the count of entries read; fractionRead() stays in [0, 1].

#include "fuzz_input.h"

#include <swslam/io/rawlog_reader.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam;
  const std::string path = fuzz::writeInput(data, size, "input.rawlog");
  io::RawlogReader reader(path);  // the file exists: opening cannot fail
  io::RawlogItem item;
  try
  {
    while (reader.next(item))
      SWSLAM_FUZZ_CHECK(!item.observation != !item.odometry_increment,
                        "an item holds exactly one of observation and odometry increment");
  }
  catch (const io::RawlogError& e)
  {
    SWSLAM_FUZZ_CHECK(e.entry() == reader.entriesRead(), e.what());
  }
  const double f = reader.fractionRead();
  SWSLAM_FUZZ_CHECK(f >= 0 && f <= 1, "fractionRead() = " + std::to_string(f));
  return 0;
}

// Harness: system::readStatsCsv over any bytes as a run's stats.csv, then the rows it read
// written (formatStatsCsv) and read again. Documented error path: std::runtime_error
// "stats.csv: '<path>' line L: ...". Promises checked: what was read writes back into a file
// that reads without error, with as many rows, and the same scan numbers, times (to the
// written microsecond), sources and direction counts.

#include "rows_round_trip.h"

#include <swslam/system/scan_stats.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam;
  fuzz::rowsRoundTrip(data, size, "stats.csv", system::readStatsCsv, system::formatStatsCsv,
                      [](const system::ScanStats& a, const system::ScanStats& b) {
                        return a.scan == b.scan && fuzz::sameStamp(a.timestamp, b.timestamp) && a.source == b.source &&
                               a.ambiguous == b.ambiguous && a.prior_decided == b.prior_decided;
                      });
  return 0;
}

// Harness: eval::readRelations over any bytes as a .relations file, then the relations it
// read written (formatRelations) and read again. Documented error path: std::runtime_error
// "relations: '<path>' line L: ...". Promises checked: what was read writes back into a file
// that reads without error, with as many relations and the same timestamps (to the written
// microsecond).

#include "rows_round_trip.h"

#include <swslam/eval/relations_io.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam;
  fuzz::rowsRoundTrip(data, size, "relations", eval::readRelations, eval::formatRelations,
                      [](const eval::Relation& a, const eval::Relation& b) {
                        return fuzz::sameStamp(a.t1, b.t1) && fuzz::sameStamp(a.t2, b.t2);
                      });
  return 0;
}

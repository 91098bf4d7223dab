#pragma once
// The harness of a reader of rows of numbers (common/number_rows.h: TUM, .relations): `read`
// the input as a file, whose only documented error is std::runtime_error
// "<what>: '<path>' line L: ..."; then `format` what it read and `read` that again, which
// must give as many rows, each `same` as the one it was written from.

#include "fuzz_input.h"

#include <algorithm>
#include <cmath>

namespace swslam::fuzz
{
/** Equal to the microsecond a timestamp is written with (%.6f). */
inline bool sameStamp(double a, double b) { return std::abs(a - b) <= 1e-6 * std::max(1.0, std::abs(a)); }

template <class Read, class Format, class Same>
void rowsRoundTrip(const uint8_t* data, size_t size, const std::string& what, Read read,
                   Format format, Same same)
{
  const std::string path = writeInput(data, size, "input." + what);
  decltype(read(path)) rows;
  try
  {
    rows = read(path);
  }
  catch (const std::runtime_error& e)
  {
    SWSLAM_FUZZ_CHECK(startsWith(e.what(), what + ": '" + path + "' line "), e.what());
    return;
  }
  const std::string text = format(rows);
  const auto back = read(writeInput(reinterpret_cast<const uint8_t*>(text.data()), text.size(),
                                    "written." + what));
  SWSLAM_FUZZ_CHECK(back.size() == rows.size(), text);
  for (size_t i = 0; i < rows.size(); ++i)
    SWSLAM_FUZZ_CHECK(same(rows[i], back[i]), "row " + std::to_string(i) + " of\n" + text);
}

}  // namespace swslam::fuzz

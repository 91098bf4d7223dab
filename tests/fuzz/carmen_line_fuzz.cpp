// Harness: io::parseCarmenLine over any bytes as one line. Documented error path:
// CarmenLineError (a known message that cannot be parsed). Promises checked: a laser line
// keeps at most 100000 beams and names a sensor; a PARAM line has a name and a value.

#include "fuzz_input.h"

#include <swslam/io/carmen_line.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try
  {
    const io::CarmenLine line = io::parseCarmenLine(text);
    if (line.kind == io::CarmenLine::Kind::Laser)
    {
      SWSLAM_FUZZ_CHECK(line.laser.ranges.size() <= 100000, line.laser.label);
      SWSLAM_FUZZ_CHECK(!io::carmenSensorOf(line.laser.label).empty(), line.laser.label);
      SWSLAM_FUZZ_CHECK(line.laser.label == line.message, line.laser.label);
    }
    if (line.kind == io::CarmenLine::Kind::Param)
      SWSLAM_FUZZ_CHECK(!line.param_name.empty() && !line.param_value.empty(), line.message);
  }
  catch (const io::CarmenLineError&)
  {
  }
  return 0;
}

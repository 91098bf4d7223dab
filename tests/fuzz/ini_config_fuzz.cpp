// Harness: the configuration the swslam programs load (system::loadSystemParams of a path:
// common::readIniFile's line check, then every module's parameters from its own section,
// strictly) over any bytes as an .ini file; then the parameters it loaded saved and loaded
// again. Documented error path: std::invalid_argument naming the file, line, section or key.
// Promises checked: loaded parameters save into a configuration that loads without error and
// saves to the same text.

#include "fuzz_input.h"

#include <swslam/system/config.h>

#include <mrpt/config/CConfigFileMemory.h>

namespace
{
std::string savedText(const swslam::system::SystemParams& params)
{
  mrpt::config::CConfigFileMemory cfg;
  swslam::system::saveSystemParams(params, cfg);
  std::string text;
  cfg.getContent(text);
  return text;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam;
  const std::string path = fuzz::writeInput(data, size, "input.ini");
  system::SystemParams params;
  try
  {
    params = system::loadSystemParams(path);
  }
  catch (const std::invalid_argument&)
  {
    return 0;
  }
  const std::string text = savedText(params);
  const system::SystemParams back = system::loadSystemParams(mrpt::config::CConfigFileMemory(text));
  SWSLAM_FUZZ_CHECK(savedText(back) == text, text);
  return 0;
}

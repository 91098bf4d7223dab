// Harness: the configuration the swslam programs load (app::loadConfig of a path:
// common::readIniFile's line check, then every module's parameters from its own section,
// strictly) over any bytes as an .ini file; then the parameters it loaded written (both tiers,
// as swslam-config writes them) and loaded again. Documented error path:
// std::invalid_argument naming the file, line, section or key. Promises checked: loaded
// parameters write into a configuration that loads without error and writes the same text.

#include "fuzz_input.h"

#include <swslam/app/config.h>

#include <mrpt/config/CConfigFileMemory.h>

namespace
{
std::string savedText(const swslam::app::Config& config)
{
  using swslam::common::Tier;
  return swslam::app::configText(config, Tier::User) + "\n" + swslam::app::configText(config, Tier::Expert);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace swslam;
  const std::string path = fuzz::writeInput(data, size, "input.ini");
  app::Config params;
  try
  {
    params = app::loadConfig(path);
  }
  catch (const std::invalid_argument&)
  {
    return 0;
  }
  const std::string text = savedText(params);
  const app::Config back = app::loadConfig(mrpt::config::CConfigFileMemory(text));
  SWSLAM_FUZZ_CHECK(savedText(back) == text, text);
  return 0;
}

#include <swslam/app/default_config.h>

#include <filesystem>
#include <stdexcept>

namespace swslam::app
{
std::vector<std::string> defaultConfigCandidates()
{
  return {SWSLAM_INSTALLED_CONFIG, SWSLAM_SOURCE_CONFIG};
}

std::string defaultConfigPath()
{
  std::string tried;
  for (const std::string& path : defaultConfigCandidates())
  {
    if (std::filesystem::is_regular_file(path)) return path;
    tried += (tried.empty() ? "" : ", ") + path;
  }
  throw std::invalid_argument("no configuration given (-c) and no default.ini at " + tried);
}

std::string configOrDefault(const std::string& given) { return given.empty() ? defaultConfigPath() : given; }

}  // namespace swslam::app

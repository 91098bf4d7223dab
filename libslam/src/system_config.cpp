#include "swslam/system_config.h"

#include "swslam/config_keys.h"

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <stdexcept>

namespace swslam
{
const std::vector<std::string>& SystemParams::sections()
{
  static const std::vector<std::string> names = {"plicp", "tracking", "carmen",
                                                 "graph_optimizer", "map"};
  return names;
}

SystemParams loadSystemParams(const mrpt::config::CConfigFileBase& cfg)
{
  checkKnownSections(cfg, SystemParams::sections());
  SystemParams p;
  p.plicp = loadStrict<PlicpParams>(cfg, "plicp");
  p.tracking = loadStrict<TrackingParams>(cfg, "tracking");
  p.carmen = loadStrict<CarmenParams>(cfg, "carmen");
  p.graph_optimizer = loadStrict<GraphOptimizerParams>(cfg, "graph_optimizer");
  p.map = loadStrict<MapParams>(cfg, "map");
  return p;
}

SystemParams loadSystemParams(const std::string& ini_path)
{
  if (!std::filesystem::is_regular_file(ini_path))
    throw std::invalid_argument("config: cannot read '" + ini_path + "'");
  return loadSystemParams(mrpt::config::CConfigFile(ini_path));
}

}  // namespace swslam

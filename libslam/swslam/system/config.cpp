#include <swslam/system/config.h>

#include <swslam/common/config_keys.h>
#include <swslam/common/ini_file.h>


#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace swslam::system
{
namespace
{
/** The module table, for const and non-const access alike. */
template <class Options, class Params>
std::vector<std::pair<std::string, Options*>> modulesOf(Params& p)
{
  return {{"plicp", &p.plicp},
          {"tracking", &p.tracking},
          {"correlative", &p.correlative},
          {"carmen", &p.carmen},
          {"graph_optimizer", &p.graph_optimizer},
          {"loop_closure", &p.loop_closure},
          {"final_refinement", &p.final_refinement},
          {"map", &p.map},
          {"system", &p.system}};
}
}  // namespace

std::vector<std::pair<std::string, mrpt::config::CLoadableOptions*>> SystemParams::modules()
{
  return modulesOf<mrpt::config::CLoadableOptions>(*this);
}

std::vector<std::pair<std::string, const mrpt::config::CLoadableOptions*>> SystemParams::modules()
    const
{
  return modulesOf<const mrpt::config::CLoadableOptions>(*this);
}

std::vector<std::string> SystemParams::sections()
{
  std::vector<std::string> names;
  for (const auto& [name, m] : SystemParams().modules()) names.push_back(name);
  return names;
}

SystemParams loadSystemParams(const mrpt::config::CConfigFileBase& cfg)
{
  return loadSystemParams(cfg, {});
}

SystemParams loadSystemParams(const mrpt::config::CConfigFileBase& cfg,
                              const std::vector<std::string>& other_sections)
{
  std::vector<std::string> allowed = SystemParams::sections();
  allowed.insert(allowed.end(), other_sections.begin(), other_sections.end());
  common::checkKnownSections(cfg, allowed);
  SystemParams p;
  for (auto& [name, module] : p.modules())
  {
    common::checkKnownKeys(cfg, name, *module);
    module->loadFromConfigFile(cfg, name);
    common::checkReadBack(cfg, name, *module);
  }
  checkCrossSectionRules(p);
  return p;
}

void checkCrossSectionRules(const SystemParams& params)
{
  if (params.tracking.dense_max_index_gap > params.loop_closure.min_index_gap)
    throw std::invalid_argument(
        "config: [tracking] dense_max_index_gap must not exceed [loop_closure] min_index_gap "
        "(a pair of nodes is either a dense neighbour or a loop candidate)");
}

void saveSystemParams(const SystemParams& params, mrpt::config::CConfigFileBase& cfg)
{
  for (const auto& [name, module] : params.modules()) module->saveToConfigFile(cfg, name);
}

SystemParams loadSystemParams(const std::string& ini_path)
{
  return loadSystemParams(*common::readIniFile(ini_path));
}

}  // namespace swslam::system

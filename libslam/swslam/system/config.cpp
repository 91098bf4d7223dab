#include <swslam/system/config.h>

#include <swslam/common/ini_file.h>

#include <stdexcept>

namespace swslam::system
{
std::vector<std::string> SystemParams::sections()
{
  std::vector<std::string> names;
  const SystemParams p;
  forEachSection(p, [&](const auto& table, const auto&) { names.push_back(table.section()); });
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
  SystemParams::forEachSection(p, [&](const auto& table, auto& params) { table.load(cfg, params); });
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
  SystemParams::forEachSection(params, [&](const auto& table, const auto& p) { table.save(p, cfg); });
}

SystemParams loadSystemParams(const std::string& ini_path)
{
  return loadSystemParams(*common::readIniFile(ini_path));
}

}  // namespace swslam::system

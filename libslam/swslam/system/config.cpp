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

std::string configText(const SystemParams& params, common::Tier tier)
{
  std::string text;
  SystemParams::forEachSection(params, [&](const auto& table, const auto& p) {
    const std::string section = table.ini(p, tier);
    if (!section.empty()) text += (text.empty() ? "" : "\n") + section;
  });
  return text;
}

std::string shippedConfigFile(common::Tier tier)
{
  const std::string header =
      tier == common::Tier::User
          ? "# swslam's configuration: the keys a user tunes, at the values behind every figure in doc/.\n"
            "# The other keys are in config/expert.ini at their defaults; any of them may be set here too,\n"
            "# under its section. An unknown section or key is an error naming it. Units in brackets;\n"
            "# angles in degrees where the key ends in _DEG. Written by swslam-config (doc/configuration.md).\n"
          : "# swslam's expert keys at their defaults, the values behind every figure in doc/. To change one,\n"
            "# copy it under its section into the file given with -c (e.g. a copy of config/default.ini).\n"
            "# An unknown section or key is an error naming it. Units in brackets; angles in degrees where\n"
            "# the key ends in _DEG. Written by swslam-config --tier expert (doc/configuration.md).\n";
  return header + "\n" + configText(SystemParams(), tier);
}

SystemParams loadSystemParams(const std::string& ini_path)
{
  return loadSystemParams(*common::readIniFile(ini_path));
}

}  // namespace swslam::system

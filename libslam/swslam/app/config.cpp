#include <swslam/app/config.h>

#include <swslam/common/ini_file.h>

namespace swslam::app
{
Config loadConfig(const mrpt::config::CConfigFileBase& cfg, const std::vector<std::string>& other_sections)
{
  std::vector<std::string> others = other_sections;
  others.push_back(io::CarmenParams::table().section());
  others.push_back(localize::LocalizationParams::table().section());
  others.push_back("run");  // a run's record (run_record.h) is a configuration too
  Config c;
  c.system = system::loadSystemParams(cfg, others);
  io::CarmenParams::table().load(cfg, c.carmen);
  localize::LocalizationParams::table().load(cfg, c.localization);
  return c;
}

Config loadConfig(const std::string& ini_path) { return loadConfig(*common::readIniFile(ini_path)); }

std::string configText(const Config& c, common::Tier tier)
{
  std::string text;
  Config::forEachSection(c, [&](const auto& table, const auto& p) {
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
  return header + "\n" + configText(Config(), tier);
}

}  // namespace swslam::app

#include "swslam/config_keys.h"

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/system/string_utils.h>

#include <algorithm>
#include <stdexcept>

namespace swslam
{
namespace
{
std::string joined(const std::vector<std::string>& v)
{
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}
}  // namespace

void checkKnownKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                    const mrpt::config::CLoadableOptions& params)
{
  mrpt::config::CConfigFileMemory known_cfg;
  params.saveToConfigFile(known_cfg, section);
  std::vector<std::string> known, present;
  known_cfg.getAllKeys(section, known);
  cfg.getAllKeys(section, present);
  // MRPT pads names when it writes commented keys: compare trimmed names.
  for (auto& k : known) k = mrpt::system::trim(k);
  for (const auto& padded_key : present)
  {
    const std::string key = mrpt::system::trim(padded_key);
    const bool ok = std::any_of(known.begin(), known.end(), [&](const std::string& k) {
      return mrpt::system::strCmpI(k, key);
    });
    if (!ok)
      throw std::invalid_argument("config: unknown key '" + key + "' in section [" + section +
                                  "]; known keys: " + joined(known));
    // MRPT's reader keeps the rest of the line in the value: "true  # note" would read as
    // false, silently. Comments go on lines of their own.
    const std::string value = cfg.read_string(section, padded_key, "");
    if (value.find(" #") != std::string::npos || value.find("\t#") != std::string::npos ||
        value.find(" ;") != std::string::npos)
      throw std::invalid_argument("config: [" + section + "] " + key + " = '" + value +
                                  "': comments must be on a line of their own");
  }
}

void checkKnownSections(const mrpt::config::CConfigFileBase& cfg,
                        const std::vector<std::string>& allowed)
{
  std::vector<std::string> sections;
  cfg.getAllSections(sections);
  for (const auto& s : sections)
  {
    if (std::find(allowed.begin(), allowed.end(), s) == allowed.end())
      throw std::invalid_argument("config: unknown section [" + s + "]; known sections: " +
                                  joined(allowed));
  }
}

}  // namespace swslam

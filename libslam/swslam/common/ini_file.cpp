#include <swslam/common/ini_file.h>

#include <mrpt/system/string_utils.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>

namespace swslam::common
{
void checkIniLines(const std::string& text, const std::string& source)
{
  std::map<std::string, size_t> seen;  // "section\nkey" (lower case) -> line
  std::string section;
  std::istringstream in(text);
  std::string raw;
  for (size_t line = 1; std::getline(in, raw); ++line)
  {
    const std::string l = mrpt::system::trim(raw);
    if (l.empty() || l[0] == '#' || l[0] == ';') continue;
    const std::string where = "config: '" + source + "' line " + std::to_string(line) + ": ";
    if (l.front() == '[' && l.back() == ']' && l.size() > 2)
    {
      section = mrpt::system::lowerCase(mrpt::system::trim(l.substr(1, l.size() - 2)));
      continue;
    }
    const size_t eq = l.find('=');
    const std::string key = eq == std::string::npos ? "" : mrpt::system::trim(l.substr(0, eq));
    if (key.empty() || key.find_first_of("[]") != std::string::npos)
      throw std::invalid_argument(where + "'" + l + "' is neither '[section]' nor 'key = value'");
    const auto [at, fresh] = seen.emplace(section + "\n" + mrpt::system::lowerCase(key), line);
    if (!fresh)
      throw std::invalid_argument(where + "key '" + key + "' of [" + section + "] is set again (first on line " +
                                  std::to_string(at->second) + ")");
  }
}

std::unique_ptr<mrpt::config::CConfigFileMemory> readIniFile(const std::string& path)
{
  std::ifstream in(path);
  if (!std::filesystem::is_regular_file(path) || !in)
    throw std::invalid_argument("config: cannot read '" + path + "'");
  const std::string text(std::istreambuf_iterator<char>(in), {});
  checkIniLines(text, path);
  try
  {
    return std::make_unique<mrpt::config::CConfigFileMemory>(text);
  }
  catch (const std::exception& e)
  {
    // MRPT expands $env{NAME} and ${expression} anywhere in the text, comments too, and
    // throws std::runtime_error on one it cannot parse (e.g. an unclosed "$env{").
    throw std::invalid_argument("config: '" + path + "': " + e.what());
  }
}

size_t readIniCount(const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
                    const std::string& source)
{
  const std::string v = cfg.read_string(section, key, "");
  const bool digits = !v.empty() && v.size() <= 19 && v.find_first_not_of("0123456789") == std::string::npos;
  if (!digits)
    throw std::invalid_argument(source + ": [" + section + "] " + key + " must be a count, got '" + v + "'");
  return static_cast<size_t>(std::stoull(v));
}

}  // namespace swslam::common

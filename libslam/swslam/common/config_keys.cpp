#include <swslam/common/config_keys.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/system/string_utils.h>

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace swslam::common
{
namespace
{
std::string joined(const std::vector<std::string>& v)
{
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

enum class ValueKind { Bool, Number, Text };

/** A value as saveToConfigFile() wrote it, without the " // comment" MRPT appends. */
std::string savedValue(const std::string& written)
{
  return mrpt::system::trim(written.substr(0, written.find("//")));
}

/** The kind of a key, from the text saveToConfigFile() writes for its default: true/false, a
 * number, or other text. (Integers cannot be told from floating-point numbers this way: some
 * savers write 2.0 as "2".) */
ValueKind kindOf(const std::string& saved)
{
  const std::string lower = mrpt::system::lowerCase(saved);
  if (lower == "true" || lower == "false") return ValueKind::Bool;
  if (saved.empty()) return ValueKind::Text;
  char* end = nullptr;
  std::strtod(saved.c_str(), &end);
  return *end == '\0' ? ValueKind::Number : ValueKind::Text;
}

/** Empty unless `value` is not one MRPT's reader takes at face value for that kind (its
 * atoi/atof read "abc" as 0 and "1 2" as 1, and a boolean "0x10" as false, all silently). */
std::string valueProblem(ValueKind kind, const std::string& value)
{
  if (value.empty()) return "has no value";
  switch (kind)
  {
    case ValueKind::Bool:
    {
      const std::string v = mrpt::system::lowerCase(value);
      for (const char* ok : {"true", "false", "yes", "no", "1", "0"})
        if (v == ok) return {};
      return "is not a boolean (true or false)";
    }
    case ValueKind::Number:
    {
      char* end = nullptr;
      const double v = std::strtod(value.c_str(), &end);
      if (*end != '\0' || std::isnan(v)) return "is not a number";
      return {};
    }
    case ValueKind::Text: return {};
  }
  return {};
}
}  // namespace

namespace
{
/** The keys and values that `params.saveToConfigFile()` writes into `section`, found by name
 * as a config file spells it (any case; MRPT pads names when it writes commented keys). */
class SavedSection
{
 public:
  SavedSection(const mrpt::config::CLoadableOptions& params, const std::string& section) : section_(section)
  {
    params.saveToConfigFile(cfg_, section);
    cfg_.getAllKeys(section, padded_);
    for (const auto& k : padded_) names_.push_back(mrpt::system::trim(k));
  }
  /** The saved value (without MRPT's appended comment) of `key`, or nullopt if not saved. */
  std::optional<std::string> value(const std::string& key) const
  {
    const auto it = std::find_if(names_.begin(), names_.end(),
                                 [&](const std::string& k) { return mrpt::system::strCmpI(k, key); });
    if (it == names_.end()) return std::nullopt;
    return savedValue(cfg_.read_string(section_, padded_[it - names_.begin()], ""));
  }
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::string section_;
  mrpt::config::CConfigFileMemory cfg_;
  std::vector<std::string> padded_, names_;
};

/** Each key of `section` in `cfg`: its trimmed name and its value as written. */
template <class Visit>
void forEachKey(const mrpt::config::CConfigFileBase& cfg, const std::string& section, Visit visit)
{
  std::vector<std::string> present;
  cfg.getAllKeys(section, present);
  for (const auto& padded_key : present)
    visit(mrpt::system::trim(padded_key), cfg.read_string(section, padded_key, ""));
}
}  // namespace

void checkKnownKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                    const mrpt::config::CLoadableOptions& params)
{
  const SavedSection known(params, section);
  forEachKey(cfg, section, [&](const std::string& key, const std::string& value) {
    const std::optional<std::string> saved = known.value(key);
    if (!saved)
      throw std::invalid_argument("config: unknown key '" + key + "' in section [" + section +
                                  "]; known keys: " + joined(known.names()));
    // MRPT's reader keeps the rest of the line in the value: "true  # note" would read as
    // false, silently. Comments go on lines of their own.
    if (value.find(" #") != std::string::npos || value.find("\t#") != std::string::npos ||
        value.find(" ;") != std::string::npos)
      throw std::invalid_argument("config: [" + section + "] " + key + " = '" + value +
                                  "': comments must be on a line of their own");
    const std::string problem = valueProblem(kindOf(*saved), value);
    if (!problem.empty())
      throw std::invalid_argument("config: [" + section + "] " + key + " = '" + value + "' " + problem);
  });
}

void checkReadBack(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                   const mrpt::config::CLoadableOptions& loaded)
{
  const SavedSection saved_section(loaded, section);
  forEachKey(cfg, section, [&](const std::string& key, const std::string& written) {
    const std::optional<std::string> saved = saved_section.value(key);
    if (!saved) return;
    // Only a value saved as a plain integer can have been truncated or wrapped. A floating-point
    // key saved that way (some savers write 2.0 as "2") was read as written, and compares equal.
    const size_t first = saved->empty() || (*saved)[0] != '-' ? 0 : 1;
    if (first == saved->size() || saved->find_first_not_of("0123456789", first) != std::string::npos) return;
    const std::string value = mrpt::system::trim(written);
    if (std::strtod(value.c_str(), nullptr) != std::strtod(saved->c_str(), nullptr))
      throw std::invalid_argument("config: [" + section + "] " + key + " = '" + value +
                                  "' is not an integer in the key's range (it would be read as " + *saved + ")");
  });
}

}  // namespace swslam::common

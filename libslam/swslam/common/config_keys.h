#pragma once
// Strict loading of the simulator's scenario sections (sim/scenario.h), whose structs are
// MRPT CLoadableOptions: a key that the struct does not know, or a value that is not of its
// key's kind, is an error naming the key, never a silent default. (The modules' parameters
// are declared in tables: common/param_table.h.)

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CLoadableOptions.h>

#include <string>
#include <vector>

namespace swslam::common
{
/** Throws std::invalid_argument if `section` of `cfg` holds a key that
 * `params.saveToConfigFile()` does not write (i.e. a key the struct does not know), or a
 * value that is empty or not of its key's kind (a boolean: true/false/yes/no/1/0; a
 * number: the whole value, +-inf allowed, not NaN), since MRPT's reader would take such a
 * value silently as 0 or as its leading part. Ranges are each struct's own check. */
void checkKnownKeys(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                    const mrpt::config::CLoadableOptions& params);

/** Call after `loaded.loadFromConfigFile(cfg, section)`. Throws std::invalid_argument if an
 * integer key of `section` was read as another number than its value says: MRPT's reader
 * takes "1e19" or "2.5" as 1 or 2 and an unsigned "-1" as 2^64 - 1, silently. Checked are the
 * keys whose loaded value `saveToConfigFile()` writes as a plain integer. */
void checkReadBack(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                   const mrpt::config::CLoadableOptions& loaded);

/** checkKnownKeys(), params.loadFromConfigFile(), then checkReadBack(). */
template <class Params>
Params loadStrict(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
  Params p;
  checkKnownKeys(cfg, section, p);
  p.loadFromConfigFile(cfg, section);
  checkReadBack(cfg, section, p);
  return p;
}

}  // namespace swslam::common

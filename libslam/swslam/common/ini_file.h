#pragma once
// The one way every program and scenario reads an .ini file: the file must exist, and every
// line must be blank, a comment, '[section]' or 'key = value', each key set once, before
// MRPT parses it (MRPT's reader skips a stray line, and keeps one of two settings, silently).
// What the sections hold is checked by each parameter struct's strict loading
// (param_table.h).

#include <mrpt/config/CConfigFileMemory.h>

#include <cstddef>
#include <memory>
#include <string>

namespace swslam::common
{
/** Throws std::invalid_argument naming `source` and the line if a line of the .ini `text` is
 * neither blank, a comment (# or ;), '[section]' nor 'key = value' (MRPT's reader skips such
 * lines silently), or sets a key its section already set (MRPT keeps one, silently). */
void checkIniLines(const std::string& text, const std::string& source);

/** The .ini file at `path`, its lines checked (checkIniLines). Throws std::invalid_argument
 * naming the file if it cannot be read, or the line that is wrong, or MRPT's message if it
 * cannot expand a $env{NAME} or ${expression} of the text (comments included). */
std::unique_ptr<mrpt::config::CConfigFileMemory> readIniFile(const std::string& path);

/** [section] key of `cfg` as a whole count (decimal digits only). Throws std::invalid_argument
 * "SOURCE: [section] key must be a count, got 'VALUE'" if it is missing or not one. */
size_t readIniCount(const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
                    const std::string& source);

}  // namespace swslam::common

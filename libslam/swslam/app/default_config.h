#pragma once
// The configuration a program uses when none is given (-c): config/default.ini as installed
// (`cmake --install`: <prefix>/share/swslam/config/default.ini), else the one of the source tree
// the program was built from.

#include <string>
#include <vector>

namespace swslam::app
{
/** Where default.ini is looked for, in order. */
std::vector<std::string> defaultConfigCandidates();

/** The first candidate that exists. Throws std::invalid_argument naming every candidate if none
 * does (pass -c). */
std::string defaultConfigPath();

/** `given` if not empty, else defaultConfigPath(). */
std::string configOrDefault(const std::string& given);

}  // namespace swslam::app

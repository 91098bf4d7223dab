#pragma once
// The .relations text files of Kuemmerle et al.'s benchmark (one relation a line).

#include <swslam/eval/relations.h>

#include <string>
#include <vector>

namespace swslam::eval
{
/** Reads a .relations file ('#' comments allowed). Throws std::runtime_error naming the
 * file and line on a malformed line. */
std::vector<Relation> readRelations(const std::string& path);

/** Formats relations as .relations text (z = roll = pitch = 0). */
std::string formatRelations(const std::vector<Relation>& relations);

}  // namespace swslam::eval

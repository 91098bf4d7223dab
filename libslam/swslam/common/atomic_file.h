#pragma once
// Outputs are written under a temporary name in the same directory and renamed into
// place, so an interrupted run never leaves a half-written file under the final name.

#include <functional>
#include <string>

namespace swslam::common
{
/** Calls `writer(tmp_path)`, which must create the file `tmp_path`, then renames it to
 * `path`. If the writer throws or creates nothing, `path` is left untouched and the
 * temporary file is removed; the exception is rethrown. */
void writeAtomically(const std::string& path,
                     const std::function<void(const std::string& tmp_path)>& writer);

/** True for the name writeAtomically() gives a file before renaming it (".NAME.tmpPID.EXT"):
 * one a process killed while writing left behind. */
bool isAtomicTemporary(const std::string& file_name);

/** Writes `content` to `path` atomically. */
void writeTextAtomically(const std::string& path, const std::string& content);

}  // namespace swslam::common

#pragma once
// Outputs are written under a temporary name in the same directory and renamed into
// place, so an interrupted run never leaves a half-written file under the final name.

#include <functional>
#include <iosfwd>
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

/** Writes `path` atomically through a file stream: `write` writes into it; the stream is then
 * closed and checked, so that data the disk refused (full: ENOSPC; a file size limit: EFBIG)
 * is an error naming the cause, and never a short file under `path`. A writer that sees the
 * stream fail may stop early (streamFailure() says why). */
void writeStreamAtomically(const std::string& path, const std::function<void(std::ostream& out)>& write);

/** Writes `content` to `path` atomically (writeStreamAtomically). */
void writeTextAtomically(const std::string& path, const std::string& content);

/** Why a file stream failed: "the disk refused the data: " and the system's reason. */
std::string streamFailure();

}  // namespace swslam::common

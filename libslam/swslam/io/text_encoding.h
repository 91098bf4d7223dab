#pragma once
// Telling a text log that is not in a byte encoding (UTF-16, UTF-32) from one that is: a
// CARMEN log saved as UTF-16 (a Windows editor's "Unicode") has a NUL byte beside every
// character, and its reader found no line it knew ("no laser scan") without saying why.

#include <string>

namespace swslam::io
{
/** The wide encoding the first bytes of a text file are in, if any ("" for ASCII, UTF-8 or
 * Latin-1): "UTF-16LE" / "UTF-16BE" / "UTF-32LE" / "UTF-32BE", from a byte order mark
 * (FF FE, FE FF, FF FE 00 00, 00 00 FE FF), or without one from the NUL bytes: at least
 * 3/4 of the odd (little-endian) or even (big-endian) positions NUL and few of the others. */
std::string wideTextEncoding(const std::string& head);

/** What to say of a text file whose first bytes `head` are in a wide encoding ("" if they are
 * not): "is UTF-16LE text (it starts with the byte order mark FF FE), not ASCII: ...". */
std::string wideTextProblem(const std::string& head);

}  // namespace swslam::io

#pragma once
// One SCIP 2.0 reply as the sensor sends it: the echo of the command, a status line
// ("00", "99", ...), the lines of data or parameters, and an empty line. Serializing can
// corrupt a reply on purpose (bad checksum, truncated line, wrong echo) to test the
// clients' error handling; parsing checks every checksum.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace swslam::scip
{
/** Ways a reply can be malformed on purpose. The corrupted line is the first one after
 * the status (the timestamp of a scan, the first parameter of PP or VV), or the status
 * line itself when there is none. */
enum class Fault
{
  None,
  BadChecksum,    ///< the line's checksum character is off by one
  TruncatedLine,  ///< the line loses its second half (checksum included) before its LF
  WrongEcho,      ///< the echo's last character is changed
};

/** "none", "bad-checksum", "truncated-line", "wrong-echo". */
const char* faultName(Fault f);
/** Inverse of faultName(); throws std::invalid_argument naming the known names. */
Fault parseFault(std::string_view name);

struct Frame
{
  std::string echo;                ///< the command as received, without its LF
  std::string status;              ///< two characters
  std::vector<std::string> lines;  ///< line bodies, without checksum nor LF
  bool info_lines = false;         ///< parameter lines ("NAME:value;" + checksum)
};

/** The bytes of `f` on the wire, corrupted as `fault` says. */
std::string serialize(const Frame& f, Fault fault = Fault::None);

struct ParsedFrame
{
  Frame frame;               ///< parameter lines lose their ';'
  bool checksums_ok = true;  ///< every line after the echo had the right checksum
  size_t bytes = 0;          ///< bytes of the frame, final empty line included
};

/** Parses the frame at the start of `bytes`: nothing if it is not complete yet. A line
 * too short to hold a checksum makes checksums_ok false. */
std::optional<ParsedFrame> parseFrame(std::string_view bytes);

}  // namespace swslam::scip

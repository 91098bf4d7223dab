#pragma once
// SCIP 2.0 character encoding, after Hokuyo's "Communication Protocol Specification for
// SCIP2.0 Standard": a number is sent as 2, 3 or 4 characters of 6 bits each (most
// significant first), each offset by 0x30; every line after the echo ends with a checksum
// character (the low 6 bits of the sum of the line's bytes, plus 0x30) and a LF.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace swslam::scip
{
/** Timestamps are 24-bit millisecond counters (4 characters) that wrap around. */
constexpr uint32_t kTimestampModulo = 1u << 24;
/** Range data lines hold at most 64 characters; a value may straddle two lines. */
constexpr size_t kBlockWidth = 64;

/** `value` as `chars` characters (1..4). Throws std::invalid_argument if `chars` is out of
 * range or `value` does not fit in 6 * chars bits. */
std::string encode(uint32_t value, int chars);

/** The value of 1..4 encoded characters. Throws std::invalid_argument on an empty or too
 * long text or a character outside 0x30..0x6F. */
uint32_t decode(std::string_view text);

/** Checksum character of a line body: (sum of its bytes & 0x3F) + 0x30. */
char checksum(std::string_view body);

/** A line of data or status: body, checksum, LF. */
std::string dataLine(std::string_view body);

/** A parameter line of the PP and VV replies: body, ';', checksum of the body, LF
 * (the ';' is not summed). */
std::string infoLine(std::string_view body);

/** `encoded` cut into consecutive lines of `width` characters (the last one shorter). */
std::vector<std::string> splitBlocks(std::string_view encoded, size_t width = kBlockWidth);

/** Decodes consecutive groups of `chars` characters; throws std::invalid_argument if the
 * length is not a multiple of `chars` or a character is invalid. */
std::vector<uint32_t> decodeValues(std::string_view encoded, int chars);

}  // namespace swslam::scip

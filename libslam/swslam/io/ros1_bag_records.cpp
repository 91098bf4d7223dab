#include <swslam/io/ros1_bag_records.h>

#include <cstdio>

namespace swslam::io::ros1
{
uint64_t littleEndian(const char* p, size_t bytes)
{
  uint64_t v = 0;
  for (size_t i = bytes; i-- > 0;) v = (v << 8) | uint8_t(p[i]);
  return v;
}

std::string opName(int op)
{
  switch (op)
  {
    case kOpMessage: return "message data";
    case kOpFileHeader: return "file header";
    case kOpIndexData: return "index data";
    case kOpChunk: return "chunk";
    case kOpChunkInfo: return "chunk info";
    case kOpConnection: return "connection";
    default:
    {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", op);
      return std::string("op ") + hex;
    }
  }
}

std::string printable(const std::string& s)
{
  std::string out;
  for (const char c : s.substr(0, 32)) out += (c >= 32 && c < 127) ? c : '?';
  return out + (s.size() > 32 ? "..." : "");
}

std::string parseHeader(const char* p, uint32_t len, Fields& out)
{
  for (uint32_t at = 0; at < len;)
  {
    if (len - at < 4) return "its header ends inside a field's length (" + std::to_string(len - at) + " bytes left)";
    const uint32_t n = u32(p + at);
    at += 4;
    if (n > len - at)
      return "a field of its header states " + std::to_string(n) + " bytes, but its header has " +
             std::to_string(len - at) + " left (a damaged header)";
    const std::string field(p + at, n);
    at += n;
    const size_t eq = field.find('=');
    if (eq == std::string::npos) return "a field of its header has no '=' (\"" + printable(field) + "\": a damaged header)";
    out[field.substr(0, eq)] = field.substr(eq + 1);
  }
  return "";
}

}  // namespace swslam::io::ros1

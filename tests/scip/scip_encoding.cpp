#include "scip_encoding.h"

#include <stdexcept>

namespace swslam::scip
{
std::string encode(uint32_t value, int chars)
{
  if (chars < 1 || chars > 4)
    throw std::invalid_argument("SCIP encoding: " + std::to_string(chars) +
                                " characters per value (1 to 4 allowed)");
  if (value >> (6 * chars))
    throw std::invalid_argument("SCIP encoding: " + std::to_string(value) + " does not fit in " +
                                std::to_string(chars) + " characters");
  std::string out(static_cast<size_t>(chars), '0');
  for (int i = chars - 1; i >= 0; i--, value >>= 6)
    out[static_cast<size_t>(i)] = static_cast<char>(0x30 + (value & 0x3F));
  return out;
}

uint32_t decode(std::string_view text)
{
  if (text.empty() || text.size() > 4)
    throw std::invalid_argument("SCIP decoding: " + std::to_string(text.size()) +
                                " characters (1 to 4 allowed)");
  uint32_t value = 0;
  for (char c : text)
  {
    const int v = static_cast<unsigned char>(c) - 0x30;
    if (v < 0 || v > 0x3F)
      throw std::invalid_argument(std::string("SCIP decoding: invalid character '") + c + "'");
    value = (value << 6) | static_cast<uint32_t>(v);
  }
  return value;
}

char checksum(std::string_view body)
{
  unsigned sum = 0;
  for (char c : body) sum += static_cast<unsigned char>(c);
  return static_cast<char>((sum & 0x3F) + 0x30);
}

std::string dataLine(std::string_view body)
{
  std::string line(body);
  line += checksum(body);
  line += '\n';
  return line;
}

std::string infoLine(std::string_view body)
{
  std::string line(body);
  line += ';';
  line += checksum(body);
  line += '\n';
  return line;
}

std::vector<std::string> splitBlocks(std::string_view encoded, size_t width)
{
  if (width == 0) throw std::invalid_argument("SCIP blocks: zero width");
  std::vector<std::string> blocks;
  for (size_t i = 0; i < encoded.size(); i += width)
    blocks.emplace_back(encoded.substr(i, width));
  return blocks;
}

std::vector<uint32_t> decodeValues(std::string_view encoded, int chars)
{
  if (chars < 1 || encoded.size() % static_cast<size_t>(chars) != 0)
    throw std::invalid_argument("SCIP decoding: " + std::to_string(encoded.size()) +
                                " characters are not a whole number of " +
                                std::to_string(chars) + "-character values");
  std::vector<uint32_t> values;
  values.reserve(encoded.size() / static_cast<size_t>(chars));
  for (size_t i = 0; i < encoded.size(); i += static_cast<size_t>(chars))
    values.push_back(decode(encoded.substr(i, static_cast<size_t>(chars))));
  return values;
}

}  // namespace swslam::scip

#pragma once
// The records of a ROS 1 bag (format 2.0), one at a time: a 4-byte header length, a header of
// fields (each a 4-byte length and "name=value"), a 4-byte data length and the data. Every
// length is checked against the bytes there are before anything is read or allocated, and a
// header as ros::Header::parse reads it (which checks neither), so that librosbag, which
// trusts them, never meets one unchecked (ros1_bag_layout.h).

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>

namespace swslam::io::ros1
{
constexpr int kOpMessage = 0x02, kOpFileHeader = 0x03, kOpIndexData = 0x04, kOpChunk = 0x05, kOpChunkInfo = 0x06,
              kOpConnection = 0x07;

/** [bytes] The longest record header (16 MiB); a connection's message definition, the longest
 * field rosbag writes, has a few KiB. */
constexpr uint32_t kMaxHeaderBytes = 16u << 20;

using Fields = std::map<std::string, std::string>;

/** An unsigned integer of `bytes` (at most 8) little-endian bytes. */
uint64_t littleEndian(const char* p, size_t bytes);
inline uint32_t u32(const char* p) { return uint32_t(littleEndian(p, 4)); }

/** "chunk", "index data", ...; "op 0x2a" for another. */
std::string opName(int op);

/** At most 32 characters of `s`, those not printable ASCII as '?'. */
std::string printable(const std::string& s);

/** The fields of a record header of `len` bytes at `p`, checked as ros::Header::parse reads
 * them (each field's length within the header, each with a '='): "" or the problem. */
std::string parseHeader(const char* p, uint32_t len, Fields& out);

/** A record: its header's fields, where its data is. */
struct Record
{
  uint64_t pos = 0;
  int op = -1;
  Fields fields;
  uint64_t data_pos = 0;
  uint32_t data_len = 0;
  uint64_t end() const { return data_pos + data_len; }
};

/** Reads the record at `pos` of bytes that end at `end`, through read(pos, n, out): "" or the
 * problem (a length past the bytes left or kMaxHeaderBytes, a damaged header, no 1-byte op). */
template <class Read>
std::string readRecord(const Read& read, uint64_t pos, uint64_t end, Record& r)
{
  r = Record{};
  r.pos = pos;
  char word[4];
  const uint64_t left = end - pos;
  if (left < 4) return "only " + std::to_string(left) + " bytes are left, too few for a record";
  read(pos, 4, word);
  const uint32_t header_len = u32(word);
  if (header_len > left - 4)
    return "its header states " + std::to_string(header_len) + " bytes, but " + std::to_string(left - 4) + " are left";
  if (header_len > kMaxHeaderBytes)
    return "its header states " + std::to_string(header_len) + " bytes, more than the " +
           std::to_string(kMaxHeaderBytes) + " a header may have";
  std::string header(header_len, '\0');
  read(pos + 4, header_len, header.data());
  if (const std::string p = parseHeader(header.data(), header_len, r.fields); !p.empty()) return p;
  const auto op = r.fields.find("op");
  if (op == r.fields.end() || op->second.size() != 1) return "its header has no op field of 1 byte (a damaged header)";
  r.op = uint8_t(op->second[0]);
  if (left - 4 - header_len < 4) return "it ends inside its data length";
  read(pos + 4 + header_len, 4, word);
  r.data_len = u32(word);
  r.data_pos = pos + 8 + header_len;
  if (r.data_len > end - r.data_pos)
    return "its data states " + std::to_string(r.data_len) + " bytes, but " + std::to_string(end - r.data_pos) +
           " are left";
  return "";
}

/** The field `name` of `r`, of `size` bytes (0: at least 1), as an integer if it has 4 or 8
 * (its text into `text` if given); fail(r, problem), which throws, if it is missing or of
 * another size. */
template <class Fail>
uint64_t field(const Record& r, const char* name, size_t size, const Fail& fail, std::string* text = nullptr)
{
  const auto it = r.fields.find(name);
  if (it == r.fields.end()) fail(r, std::string("its header has no '") + name + "' field (a damaged header)");
  if (size ? it->second.size() != size : it->second.empty())
    fail(r, std::string("its '") + name + "' field has " + std::to_string(it->second.size()) + " bytes, not " +
                (size ? std::to_string(size) : "at least 1") + " (a damaged header)");
  if (text) *text = it->second;
  return (size == 4 || size == 8) ? littleEndian(it->second.data(), size) : 0;
}

/** Whether a time is one librosbag takes (it skips another index entry with a line of its own,
 * or throws); as ns. */
inline bool validTime(uint32_t sec, uint32_t nsec) { return nsec < 1000000000u && (sec != 0 || nsec != 0); }
inline uint64_t nanoseconds(uint32_t sec, uint32_t nsec) { return uint64_t(sec) * 1000000000u + nsec; }

}  // namespace swslam::io::ros1

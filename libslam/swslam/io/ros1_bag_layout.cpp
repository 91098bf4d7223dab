#include <swslam/io/ros1_bag_layout.h>

#include <bzlib.h>
#include <roslz4/lz4s.h>

#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

namespace swslam::io
{
namespace
{
constexpr int kOpMessage = 0x02, kOpFileHeader = 0x03, kOpIndexData = 0x04, kOpChunk = 0x05, kOpChunkInfo = 0x06,
              kOpConnection = 0x07;
constexpr char kVersionLine[] = "#ROSBAG V2.0\n";
constexpr size_t kVersionBytes = sizeof(kVersionLine) - 1;
const std::string kReindex = "`rosbag reindex` rebuilds it";

using Fields = std::map<std::string, std::string>;

uint64_t littleEndian(const char* p, size_t bytes)
{
  uint64_t v = 0;
  for (size_t i = bytes; i-- > 0;) v = (v << 8) | uint8_t(p[i]);
  return v;
}
uint32_t u32(const char* p) { return uint32_t(littleEndian(p, 4)); }

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

/** The fields of a record header of `len` bytes at `p`, checked as ros::Header::parse reads
 * them (it checks neither a field's length against the header's nor the bytes of the length
 * itself): "" or the problem. */
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
 * problem (a length past the bytes left, a damaged header, no 1-byte op). */
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
  if (header_len > kMaxBagHeaderBytes)
    return "its header states " + std::to_string(header_len) + " bytes, more than the " +
           std::to_string(kMaxBagHeaderBytes) + " a header may have";
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

/** The field `name` of `r`, of `size` bytes (0: at least 1), as an integer if it has 4 or 8; a
 * std::runtime_error through `fail` if it is missing or of another size. */
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

/** A time packed as rosbag packs it (seconds in the low 32 bits, nanoseconds in the high), in
 * ns; or a problem if not a valid ROS time (librosbag skips such an index entry with a line of
 * its own, or throws). */
bool validTime(uint32_t sec, uint32_t nsec) { return nsec < 1000000000u && (sec != 0 || nsec != 0); }
uint64_t nanoseconds(uint32_t sec, uint32_t nsec) { return uint64_t(sec) * 1000000000u + nsec; }
}  // namespace

Ros1BagLayout readRos1BagLayout(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot open bag '" + path + "'");
  const uint64_t size = std::filesystem::file_size(path);
  const auto read = [&](uint64_t pos, size_t n, char* out) {
    f.seekg(std::streamoff(pos));
    if (!f.read(out, std::streamsize(n)))
      throw std::runtime_error("bag '" + path + "': cannot read byte " + std::to_string(pos));
  };
  const auto damaged = [&](const std::string& what) { throw std::runtime_error("bag '" + path + "' is damaged: " + what); };

  std::string version(kVersionBytes, '\0');
  f.read(version.data(), std::streamsize(kVersionBytes));
  if (version != kVersionLine)
    throw std::runtime_error("bag '" + path + "' is not a ROS bag of version 2.0 (its first line is \"" +
                             printable(version.substr(0, version.find('\n'))) + "\"; this program reads 2.0)");

  // The file header: where the index is, and what it holds.
  Record head;
  if (const std::string p = readRecord(read, kVersionBytes, size, head); !p.empty())
    damaged("its file header (the record at byte " + std::to_string(kVersionBytes) + "): " + p);
  const auto headFail = [&](const Record&, const std::string& what) { damaged("its file header: " + what); };
  if (head.op != kOpFileHeader) headFail(head, "the first record is a " + opName(head.op) + " (a damaged header)");
  const uint64_t index_pos = field(head, "index_pos", 8, headFail);
  const uint64_t connections = field(head, "conn_count", 4, headFail);
  const uint64_t chunk_count = field(head, "chunk_count", 4, headFail);
  if (const auto e = head.fields.find("encryptor"); e != head.fields.end() && e->second != "rosbag/NoEncryptor")
    throw std::runtime_error("bag '" + path + "' is encrypted (" + printable(e->second) +
                             "): this program reads unencrypted bags (`rosbag decrypt` writes one)");
  if (index_pos == 0)
    throw std::runtime_error("bag '" + path + "' has no index: its recording was cut short (`rosbag reindex` "
                             "rebuilds the index)");
  if (index_pos > size)
    throw std::runtime_error("cannot read bag '" + path + "': its file header places the index at byte " +
                             std::to_string(index_pos) + ", past its end at byte " + std::to_string(size) +
                             " (a truncated bag has lost its index, which is written at its end: " + kReindex +
                             "; or its file header is damaged)");
  if (index_pos < head.end())
    headFail(head, "it places the index at byte " + std::to_string(index_pos) + ", inside itself");

  // The chunks, each followed by its index data records.
  struct ChunkRecords
  {
    Record chunk;
    std::vector<Record> index;
  };
  std::vector<ChunkRecords> chunk_records;
  std::map<uint64_t, size_t> chunk_at;  // a chunk record's byte -> its chunk_records
  const std::string before_index = " (before the index at byte " + std::to_string(index_pos) + ")";
  for (uint64_t pos = head.end(); pos < index_pos;)
  {
    Record r;
    if (const std::string p = readRecord(read, pos, index_pos, r); !p.empty())
      damaged("the record at byte " + std::to_string(pos) + (r.op >= 0 ? " (a " + opName(r.op) + ")" : "") + ": " +
              p + before_index);
    const auto fail = [&](const Record& rec, const std::string& what) {
      damaged("the " + opName(rec.op) + " record at byte " + std::to_string(rec.pos) + ": " + what);
    };
    if (r.op == kOpChunk)
    {
      field(r, "compression", 0, fail);
      field(r, "size", 4, fail);
      chunk_at[pos] = chunk_records.size();
      chunk_records.push_back({r, {}});
    }
    else if (r.op == kOpIndexData)
    {
      if (field(r, "ver", 4, fail) != 1) fail(r, "its version is not 1");
      field(r, "conn", 4, fail);
      const uint64_t count = field(r, "count", 4, fail);
      if (r.data_len != 12 * count)
        fail(r, "it states " + std::to_string(count) + " entries of 12 bytes, but its data has " +
                    std::to_string(r.data_len) + " bytes");
      if (chunk_records.empty()) fail(r, "it comes before any chunk");
      chunk_records.back().index.push_back(r);
    }
    else
      fail(r, "a record of this kind where only chunks and their index data are");
    pos = r.end();
  }

  // The index: the connections, then a chunk info per chunk.
  const std::string lost = " (the index, at the bag's end, is cut short or damaged: " + kReindex + ")";
  std::set<uint32_t> connection_ids;
  std::vector<Record> infos;
  uint64_t pos = index_pos;
  for (uint64_t i = 0; i < connections + chunk_count; i++)
  {
    const bool is_connection = i < connections;
    const std::string what = is_connection ? "connection " + std::to_string(i + 1) + " of " + std::to_string(connections)
                                           : "chunk info " + std::to_string(i - connections + 1) + " of " +
                                                 std::to_string(chunk_count);
    Record r;
    if (const std::string p = readRecord(read, pos, size, r); !p.empty())
      damaged("its index: " + what + " at byte " + std::to_string(pos) + ": " + p + lost);
    const auto fail = [&](const Record& rec, const std::string& problem) {
      damaged("its index: " + what + " at byte " + std::to_string(rec.pos) + ": " + problem + lost);
    };
    if (r.op != (is_connection ? kOpConnection : kOpChunkInfo)) fail(r, "a " + opName(r.op) + " record is there");
    if (is_connection)
    {
      connection_ids.insert(uint32_t(field(r, "conn", 4, fail)));
      field(r, "topic", 0, fail);
      std::string data(r.data_len, '\0');  // read by librosbag as a header
      read(r.data_pos, r.data_len, data.data());
      Fields connection_header;
      if (const std::string p = parseHeader(data.data(), r.data_len, connection_header); !p.empty())
        fail(r, "its connection header: " + p);
    }
    else
    {
      if (field(r, "ver", 4, fail) != 1) fail(r, "its version is not 1");
      for (const char* name : {"chunk_pos", "start_time", "end_time"}) field(r, name, 8, fail);
      const uint64_t count = field(r, "count", 4, fail);
      if (r.data_len != 8 * count)
        fail(r, "it states " + std::to_string(count) + " connections of 8 bytes, but its data has " +
                    std::to_string(r.data_len) + " bytes");
      infos.push_back(r);
    }
    pos = r.end();
  }
  if (pos != size)
    damaged("its index ends at byte " + std::to_string(pos) + ", but the file goes on to byte " + std::to_string(size) +
            " (its file header states " + std::to_string(connections) + " connections and " +
            std::to_string(chunk_count) + " chunks: a damaged header?)");

  // Each chunk info: its chunk, and the index data after it (librosbag reads one per
  // connection of the chunk info, whatever follows).
  Ros1BagLayout layout;
  for (size_t i = 0; i < infos.size(); i++)
  {
    const Record& info = infos[i];
    const auto fail = [&](const Record&, const std::string& problem) {
      damaged("chunk info " + std::to_string(i + 1) + " of " + std::to_string(infos.size()) + " (byte " +
              std::to_string(info.pos) + "): " + problem);
    };
    const uint64_t chunk_pos = field(info, "chunk_pos", 8, fail);
    const auto found = chunk_at.find(chunk_pos);
    if (found == chunk_at.end())
      fail(info, "it places a chunk at byte " + std::to_string(chunk_pos) + ", where no chunk record starts");
    const ChunkRecords& records = chunk_records[found->second];
    Ros1Chunk chunk;
    chunk.pos = chunk_pos;
    chunk.data_pos = records.chunk.data_pos;
    chunk.data_len = records.chunk.data_len;
    chunk.size = uint32_t(field(records.chunk, "size", 4, fail));
    field(records.chunk, "compression", 0, fail, &chunk.compression);
    uint64_t times[2];
    const char* time_names[2] = {"start_time", "end_time"};
    for (int k = 0; k < 2; k++)
    {
      const uint64_t packed = field(info, time_names[k], 8, fail);
      if (uint32_t(packed >> 32) >= 1000000000u)
        fail(info, std::string("its ") + time_names[k] + " has " + std::to_string(packed >> 32) + " ns");
      times[k] = nanoseconds(uint32_t(packed), uint32_t(packed >> 32));
    }
    chunk.start_ns = times[0];
    chunk.end_ns = times[1];
    std::string pairs(info.data_len, '\0');
    read(info.data_pos, info.data_len, pairs.data());
    std::set<uint32_t> chunk_connections;
    for (size_t k = 0; k + 8 <= pairs.size(); k += 8) chunk_connections.insert(u32(&pairs[k]));
    if (records.index.size() < chunk_connections.size())
      fail(info, "it lists " + std::to_string(chunk_connections.size()) + " connections, but its chunk at byte " +
                     std::to_string(chunk_pos) + " is followed by " + std::to_string(records.index.size()) +
                     " index data records");
    for (size_t k = 0; k < chunk_connections.size(); k++)
    {
      const Record& index = records.index[k];
      const auto index_fail = [&](const Record&, const std::string& problem) {
        damaged("the index data record at byte " + std::to_string(index.pos) + " (of the chunk at byte " +
                std::to_string(chunk_pos) + "): " + problem);
      };
      const auto conn = uint32_t(field(index, "conn", 4, index_fail));
      if (!connection_ids.count(conn)) index_fail(index, "its connection " + std::to_string(conn) + " is not in the index");
      std::string entries(index.data_len, '\0');
      read(index.data_pos, index.data_len, entries.data());
      for (size_t e = 0; e + 12 <= entries.size(); e += 12)
      {
        const uint32_t sec = u32(&entries[e]), nsec = u32(&entries[e + 4]);
        const uint64_t t = nanoseconds(sec, nsec);
        if (!validTime(sec, nsec) || t < chunk.start_ns || t > chunk.end_ns)
          index_fail(index, "entry " + std::to_string(e / 12 + 1) + " is at time " + std::to_string(sec) + " s " +
                                std::to_string(nsec) + " ns, not a valid time within its chunk's");
        chunk.offsets.push_back(u32(&entries[e + 8]));
      }
    }
    layout.chunks.push_back(std::move(chunk));
  }
  return layout;
}

std::string ros1ChunkProblem(std::ifstream& file, const Ros1Chunk& chunk)
{
  const std::string& c = chunk.compression;
  if (c != "none" && c != "bz2" && c != "lz4") return "its compression is '" + printable(c) + "' (none, bz2 and lz4 are read)";
  for (const uint32_t bytes : {chunk.size, chunk.data_len})
    if (bytes > kMaxBagChunkBytes)
      return "it states " + std::to_string(bytes) + (bytes == chunk.size ? " bytes uncompressed" : " bytes of data") +
             ", more than the " + std::to_string(kMaxBagChunkBytes) + " a chunk may hold";
  if (c == "none" && chunk.size != chunk.data_len)
    return "uncompressed, it states " + std::to_string(chunk.size) + " bytes, but holds " + std::to_string(chunk.data_len);
  std::vector<char> data(chunk.data_len);
  file.clear();
  file.seekg(std::streamoff(chunk.data_pos));
  if (!file.read(data.data(), std::streamsize(data.size()))) return "its data cannot be read";
  std::vector<char> bytes;
  if (c == "none")
    bytes = std::move(data);
  else
  {
    bytes.resize(chunk.size);
    unsigned int n = chunk.size;
    const int rc = c == "bz2" ? BZ2_bzBuffToBuffDecompress(bytes.data(), &n, data.data(), chunk.data_len, 0, 0)
                              : roslz4_buffToBuffDecompress(data.data(), chunk.data_len, bytes.data(), &n);
    if (rc != (c == "bz2" ? BZ_OK : ROSLZ4_OK))
      return "its " + c + " data cannot be decompressed to the " + std::to_string(chunk.size) + " bytes it states (error " +
             std::to_string(rc) + ")";
    if (n != chunk.size)
      return "its " + c + " data decompresses to " + std::to_string(n) + " bytes, not the " + std::to_string(chunk.size) +
             " it states";
  }
  std::map<uint64_t, int> records;  // where each record starts -> its op
  const auto read = [&](uint64_t pos, size_t n, char* out) { std::memcpy(out, bytes.data() + pos, n); };
  for (uint64_t pos = 0; pos < bytes.size();)
  {
    Record r;
    if (const std::string p = readRecord(read, pos, bytes.size(), r); !p.empty())
      return "the record at byte " + std::to_string(pos) + " of its " + std::to_string(bytes.size()) +
             " uncompressed bytes: " + p;
    records[pos] = r.op;
    pos = r.end();
  }
  for (const uint32_t offset : chunk.offsets)
    if (const auto it = records.find(offset); it == records.end() || it->second != kOpMessage)
      return "its index places a message at byte " + std::to_string(offset) + " of its uncompressed data, where " +
             (it == records.end() ? "no record starts" : "a " + opName(it->second) + " record is");
  return "";
}

}  // namespace swslam::io

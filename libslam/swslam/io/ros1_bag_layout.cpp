#include <swslam/io/ros1_bag_layout.h>

#include <swslam/io/ros1_bag_records.h>

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
using namespace ros1;
constexpr char kVersionLine[] = "#ROSBAG V2.0\n";
constexpr size_t kVersionBytes = sizeof(kVersionLine) - 1;
const std::string kReindex = "`rosbag reindex` rebuilds it";

/** One pass over a bag's records outside its chunks (readRos1BagLayout). */
class Walk
{
 public:
  explicit Walk(const std::string& path) : path_(path), f_(path, std::ios::binary)
  {
    if (!f_) throw std::runtime_error("cannot open bag '" + path + "'");
    size_ = std::filesystem::file_size(path);
  }

  Ros1BagLayout run()
  {
    fileHeader();
    chunkRecords();
    index();
    Ros1BagLayout layout;
    for (size_t i = 0; i < infos_.size(); i++) layout.chunks.push_back(chunkOf(i));
    return layout;
  }

 private:
  struct ChunkRecords
  {
    Record chunk;
    std::vector<Record> index;  ///< the index data records after it
  };

  [[noreturn]] void damaged(const std::string& what) const
  {
    throw std::runtime_error("bag '" + path_ + "' is damaged: " + what);
  }
  void read(uint64_t pos, size_t n, char* out)
  {
    f_.seekg(std::streamoff(pos));
    if (!f_.read(out, std::streamsize(n))) throw std::runtime_error("bag '" + path_ + "': cannot read byte " + std::to_string(pos));
  }
  std::string readRecordAt(uint64_t pos, uint64_t end, Record& r)
  {
    return readRecord([this](uint64_t at, size_t n, char* out) { read(at, n, out); }, pos, end, r);
  }
  std::string bytesOf(const Record& r)
  {
    std::string data(r.data_len, '\0');
    read(r.data_pos, r.data_len, data.data());
    return data;
  }

  /** The version line and the file header: where the index is, and what it holds. */
  void fileHeader()
  {
    std::string version(kVersionBytes, '\0');
    f_.read(version.data(), std::streamsize(kVersionBytes));
    if (version != kVersionLine)
      throw std::runtime_error("bag '" + path_ + "' is not a ROS bag of version 2.0 (its first line is \"" +
                               printable(version.substr(0, version.find('\n'))) + "\"; this program reads 2.0)");
    if (const std::string p = readRecordAt(kVersionBytes, size_, head_); !p.empty())
      damaged("its file header (the record at byte " + std::to_string(kVersionBytes) + "): " + p);
    const auto fail = [&](const Record&, const std::string& what) { damaged("its file header: " + what); };
    if (head_.op != kOpFileHeader) fail(head_, "the first record is a " + opName(head_.op) + " (a damaged header)");
    index_pos_ = field(head_, "index_pos", 8, fail);
    connections_ = field(head_, "conn_count", 4, fail);
    chunk_count_ = field(head_, "chunk_count", 4, fail);
    if (const auto e = head_.fields.find("encryptor"); e != head_.fields.end() && e->second != "rosbag/NoEncryptor")
      throw std::runtime_error("bag '" + path_ + "' is encrypted (" + printable(e->second) +
                               "): this program reads unencrypted bags (`rosbag decrypt` writes one)");
    if (index_pos_ == 0)
      throw std::runtime_error("bag '" + path_ + "' has no index: its recording was cut short (`rosbag reindex` "
                               "rebuilds the index)");
    if (index_pos_ > size_)
      throw std::runtime_error("cannot read bag '" + path_ + "': its file header places the index at byte " +
                               std::to_string(index_pos_) + ", past its end at byte " + std::to_string(size_) +
                               " (a truncated bag has lost its index, which is written at its end: " + kReindex +
                               "; or its file header is damaged)");
    if (index_pos_ < head_.end()) fail(head_, "it places the index at byte " + std::to_string(index_pos_) + ", inside itself");
  }

  /** The chunks, each followed by its index data records, up to the index. */
  void chunkRecords()
  {
    const std::string before_index = " (before the index at byte " + std::to_string(index_pos_) + ")";
    for (uint64_t pos = head_.end(); pos < index_pos_;)
    {
      Record r;
      if (const std::string p = readRecordAt(pos, index_pos_, r); !p.empty())
        damaged("the record at byte " + std::to_string(pos) + (r.op >= 0 ? " (a " + opName(r.op) + ")" : "") + ": " +
                p + before_index);
      const auto fail = [&](const Record& rec, const std::string& what) {
        damaged("the " + opName(rec.op) + " record at byte " + std::to_string(rec.pos) + ": " + what);
      };
      if (r.op == kOpChunk)
      {
        field(r, "compression", 0, fail);
        field(r, "size", 4, fail);
        chunk_at_[pos] = chunk_records_.size();
        chunk_records_.push_back({r, {}});
      }
      else if (r.op == kOpIndexData)
      {
        if (field(r, "ver", 4, fail) != 1) fail(r, "its version is not 1");
        field(r, "conn", 4, fail);
        const uint64_t count = field(r, "count", 4, fail);
        if (r.data_len != 12 * count)
          fail(r, "it states " + std::to_string(count) + " entries of 12 bytes, but its data has " +
                      std::to_string(r.data_len) + " bytes");
        if (chunk_records_.empty()) fail(r, "it comes before any chunk");
        chunk_records_.back().index.push_back(r);
      }
      else
        fail(r, "a record of this kind where only chunks and their index data are");
      pos = r.end();
    }
  }

  /** The index: the connections, then a chunk info per chunk, then the file's end. */
  void index()
  {
    const std::string lost = " (the index, at the bag's end, is cut short or damaged: " + kReindex + ")";
    uint64_t pos = index_pos_;
    for (uint64_t i = 0; i < connections_ + chunk_count_; i++)
    {
      const bool is_connection = i < connections_;
      const std::string what = is_connection
                                   ? "connection " + std::to_string(i + 1) + " of " + std::to_string(connections_)
                                   : "chunk info " + std::to_string(i - connections_ + 1) + " of " +
                                         std::to_string(chunk_count_);
      Record r;
      if (const std::string p = readRecordAt(pos, size_, r); !p.empty())
        damaged("its index: " + what + " at byte " + std::to_string(pos) + ": " + p + lost);
      const auto fail = [&](const Record& rec, const std::string& problem) {
        damaged("its index: " + what + " at byte " + std::to_string(rec.pos) + ": " + problem + lost);
      };
      if (r.op != (is_connection ? kOpConnection : kOpChunkInfo)) fail(r, "a " + opName(r.op) + " record is there");
      if (is_connection)
      {
        connection_ids_.insert(uint32_t(field(r, "conn", 4, fail)));
        field(r, "topic", 0, fail);
        const std::string data = bytesOf(r);  // read by librosbag as a header
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
        infos_.push_back(r);
      }
      pos = r.end();
    }
    if (pos != size_)
      damaged("its index ends at byte " + std::to_string(pos) + ", but the file goes on to byte " + std::to_string(size_) +
              " (its file header states " + std::to_string(connections_) + " connections and " +
              std::to_string(chunk_count_) + " chunks: a damaged header?)");
  }

  /** Chunk info i: its chunk, and the index data after it (librosbag reads one per connection
   * of the chunk info, whatever follows), each entry within the chunk's times. */
  Ros1Chunk chunkOf(size_t i)
  {
    const Record& info = infos_[i];
    const auto fail = [&](const Record&, const std::string& problem) {
      damaged("chunk info " + std::to_string(i + 1) + " of " + std::to_string(infos_.size()) + " (byte " +
              std::to_string(info.pos) + "): " + problem);
    };
    const uint64_t chunk_pos = field(info, "chunk_pos", 8, fail);
    const auto found = chunk_at_.find(chunk_pos);
    if (found == chunk_at_.end())
      fail(info, "it places a chunk at byte " + std::to_string(chunk_pos) + ", where no chunk record starts");
    const ChunkRecords& records = chunk_records_[found->second];
    Ros1Chunk chunk;
    chunk.pos = chunk_pos;
    chunk.data_pos = records.chunk.data_pos;
    chunk.data_len = records.chunk.data_len;
    chunk.size = uint32_t(field(records.chunk, "size", 4, fail));
    field(records.chunk, "compression", 0, fail, &chunk.compression);
    uint64_t* times[2] = {&chunk.start_ns, &chunk.end_ns};
    const char* time_names[2] = {"start_time", "end_time"};
    for (int k = 0; k < 2; k++)
    {
      const uint64_t packed = field(info, time_names[k], 8, fail);
      if (uint32_t(packed >> 32) >= 1000000000u)
        fail(info, std::string("its ") + time_names[k] + " has " + std::to_string(packed >> 32) + " ns");
      *times[k] = nanoseconds(uint32_t(packed), uint32_t(packed >> 32));
    }
    const std::string pairs = bytesOf(info);
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
      if (!connection_ids_.count(conn)) index_fail(index, "its connection " + std::to_string(conn) + " is not in the index");
      const std::string entries = bytesOf(index);
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
    return chunk;
  }

  std::string path_;
  std::ifstream f_;
  uint64_t size_ = 0;
  Record head_;
  uint64_t index_pos_ = 0, connections_ = 0, chunk_count_ = 0;
  std::vector<ChunkRecords> chunk_records_;
  std::map<uint64_t, size_t> chunk_at_;  ///< a chunk record's byte -> its chunk_records_
  std::set<uint32_t> connection_ids_;
  std::vector<Record> infos_;
};
}  // namespace

Ros1BagLayout readRos1BagLayout(const std::string& path) { return Walk(path).run(); }

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

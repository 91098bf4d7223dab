#pragma once
// A streaming reader of MCAP files (https://mcap.dev/spec, version 0): the magic, then records
// of an opcode byte and a u64 length. It reads Header, Schema, Channel and Message records and
// opens Chunks (compression "", "zstd" or "lz4", the uncompressed size and CRC checked); it
// skips the index and summary records, and stops at DataEnd or the Footer. Every length read
// from the file is checked against the bytes left before anything is allocated or read; a
// chunk's uncompressed size is bounded by kMaxMcapChunkBytes and by the most its compression
// can expand the bytes present. One chunk is held in memory at a time.

#include <cstdint>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace swslam::io
{
namespace mcap
{
/** The file's magic, at its start and end, and the opcodes of the records (mcap_writer.h writes
 * them too). */
constexpr uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
enum Opcode : uint8_t
{
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kStatistics = 0x0B,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};
}  // namespace mcap

/** An MCAP file that cannot be read: "MCAP record at byte N: ..." (N its offset in the file;
 * in a chunk, also the record's offset in the uncompressed chunk). */
class McapError : public std::runtime_error
{
 public:
  using std::runtime_error::runtime_error;
};

/** [bytes] The largest chunk, compressed or not, this reader holds (1 GiB): rosbag2 writes
 * chunks of 768 KiB, the MCAP library's default is 1 MiB; a larger size is damage. */
constexpr uint64_t kMaxMcapChunkBytes = uint64_t(1) << 30;

/** The most bytes `compressed` bytes of `compression` can decompress to (beyond it the stated
 * size is damage): lz4 255 per byte (a match length grows by 255 per extra byte) plus its
 * frame's 64 KiB block, zstd 32768 per byte (an RLE block of 128 KiB takes 4 bytes), none
 * the bytes themselves. */
uint64_t mcapExpansionBound(const std::string& compression, uint64_t compressed);

struct McapChannel
{
  uint16_t id = 0;
  std::string topic;
  std::string message_encoding;  ///< "cdr" for ROS 2
  std::string schema_name;       ///< its schema's name, e.g. sensor_msgs/msg/LaserScan ("" none)
};

struct McapMessage
{
  uint16_t channel_id = 0;
  uint64_t log_time = 0;  ///< [ns]
  std::vector<uint8_t> data;
};

class McapReader
{
 public:
  /** Opens `path` and reads its magic and Header. Throws McapError (not MCAP, a bad Header)
   * or std::runtime_error (cannot open). */
  explicit McapReader(const std::string& path);

  /** The next Message, in file order (Schemas and Channels on the way are recorded); false at
   * DataEnd, the Footer or the end of the file. Throws McapError on a damaged record (the
   * messages before it stay valid; the next call returns false). */
  bool next(McapMessage& out);

  /** The channels seen so far, by id. */
  const std::map<uint16_t, McapChannel>& channels() const { return channels_; }
  /** Bytes of the file read so far, and its size. */
  uint64_t offset() const { return offset_; }
  uint64_t fileSize() const { return size_; }

 private:
  /** Reads the next top-level record into record_; false at the end. */
  bool nextRecord();
  /** Decompresses the Chunk record in record_ into chunk_. */
  void openChunk();
  /** Takes one record of `body` (Schema, Channel or Message; others ignored); true if it was
   * a Message, written to `out`. */
  bool take(uint8_t opcode, const uint8_t* body, uint64_t size, McapMessage& out, const std::string& where);
  [[noreturn]] void fail(uint64_t at, const std::string& what);

  std::string path_;
  std::ifstream file_;
  uint64_t size_ = 0, offset_ = 0;
  bool done_ = false;
  uint8_t opcode_ = 0;
  uint64_t record_at_ = 0;       ///< the current top-level record's offset
  std::vector<uint8_t> record_;  ///< its body
  std::vector<uint8_t> chunk_;   ///< the open chunk's records, uncompressed
  uint64_t chunk_at_ = 0;        ///< the next record's offset in chunk_
  std::map<uint16_t, std::string> schemas_;  ///< names by id
  std::map<uint16_t, McapChannel> channels_;
};

/** Whether `path` starts with the MCAP magic (0x89 "MCAP0" CR LF). */
bool hasMcapMagic(const std::string& path);

}  // namespace swslam::io

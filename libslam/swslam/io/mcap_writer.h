#pragma once
// An MCAP writer (https://mcap.dev/spec, version 0), as rosbag2 writes its .mcap files: the
// Header, each Schema and Channel once before its first message, the messages in uncompressed
// Chunks of about kMcapChunkBytes, each followed by its Message Index records, then DataEnd and a
// summary (the Schemas, Channels, Statistics and Chunk Indexes, with a Summary Offset per group)
// that an indexed reader reads first. The counterpart of mcap_reader.h; checked by the MCAP
// project's own reader in tests/ros2/ (npm @mcap/core).

#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace swslam::io
{
/** [bytes] A chunk is closed past this size (rosbag2's default, 768 KiB). */
constexpr size_t kMcapChunkBytes = 768 * 1024;

class McapWriter
{
 public:
  /** Creates `path` and writes the magic and Header. Throws std::runtime_error naming it. */
  McapWriter(const std::string& path, const std::string& profile, const std::string& library);

  uint16_t addSchema(const std::string& name, const std::string& encoding, const std::string& data);
  uint16_t addChannel(uint16_t schema, const std::string& topic, const std::string& message_encoding,
                      const std::map<std::string, std::string>& metadata = {});
  /** A message of `channel` at `log_time` (ns), also its publish time. */
  void write(uint16_t channel, uint64_t log_time, const std::vector<uint8_t>& data);
  /** Ends the file (the last chunk, DataEnd, the summary, the Footer). Throws
   * std::runtime_error naming the file if it could not be written whole. */
  void close();

 private:
  void record(uint8_t opcode, const std::vector<uint8_t>& body);
  void closeChunk();

  std::string path_;
  std::ofstream file_;
  uint64_t pos_ = 0;
  std::vector<std::vector<uint8_t>> schemas_, channels_;  ///< their records, for the summary
  std::vector<uint8_t> chunk_;                           ///< the open chunk's records
  uint64_t chunk_start_ = 0, chunk_end_ = 0;
  std::map<uint16_t, std::vector<std::pair<uint64_t, uint64_t>>> chunk_index_;  ///< channel -> (time, offset)
  std::vector<std::vector<uint8_t>> chunk_indexes_;                            ///< Chunk Index bodies
  std::map<uint16_t, uint64_t> counts_;                                         ///< messages by channel
  uint64_t messages_ = 0, first_ = 0, last_ = 0;
  uint32_t sequence_ = 0;
};

}  // namespace swslam::io

#pragma once
// The records of a ROS 1 bag (format 2.0), checked before librosbag reads them. librosbag
// trusts every length in the file: a header or data length past the file's end reserves up
// to 4 GiB and asserts (`rosbag::Buffer::ensureCapacity`), a header field's length past its
// header is read out of bounds (after a stray "Received an invalid TCPROS header" line), an
// index offset past its chunk is copied from out of bounds. So every record is checked here
// against the bytes there are: the ones outside the chunks (file header, chunks' headers,
// index data, connections, chunk infos) when the bag is opened, and a chunk's own records
// (decompressed, at most kMaxBagChunkBytes) before librosbag reads a message of it.
//
// Layout (http://wiki.ros.org/Bags/Format/2.0): "#ROSBAG V2.0\n", then records of a 4-byte
// header length, a header of fields (each a 4-byte length and "name=value"), a 4-byte data
// length and the data. The file header (op 0x03) places the index: the connection records
// (0x07) and one chunk info (0x06) per chunk. Each chunk (0x05) is followed by an index data
// record (0x04) per connection in it, whose entries give each message's time and offset in
// the chunk's uncompressed data.

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace swslam::io
{
/** [bytes] The most a chunk may hold, uncompressed or compressed (256 MiB): rosbag closes a
 * chunk past 768 KiB (`rosbag record --chunksize`), so a chunk holds that and at most one
 * message (64 MiB, BagReader's bound); a larger stated size is damage. */
constexpr uint32_t kMaxBagChunkBytes = 256u << 20;

struct Ros1Chunk
{
  uint64_t pos = 0;       ///< byte of its record in the file
  uint64_t data_pos = 0;  ///< byte of its data in the file
  uint32_t data_len = 0;
  uint32_t size = 0;  ///< uncompressed, as its header states
  std::string compression;
  uint64_t start_ns = 0, end_ns = 0;  ///< its messages' times, by its chunk info record
  /** Its messages' records in its uncompressed data, by the index data records after it. */
  std::vector<uint32_t> offsets;
};

/** The chunks of a ROS 1 bag, in the order of its index. */
struct Ros1BagLayout
{
  std::vector<Ros1Chunk> chunks;
};

/** Reads and checks the records of the bag at `path` outside its chunks: the version line;
 * each record's header and data lengths against the bytes left, its header's fields (each
 * within the header, with a '=') and those librosbag reads (their sizes; the op); the index
 * where the file header places it, with as many connections and chunk infos as it states;
 * each chunk info at a chunk record followed by an index data record per connection in it;
 * each index entry of a known connection, at a valid time within its chunk's. Throws
 * std::runtime_error: "bag 'P' is damaged: <record> at byte N: <what it states, what there
 * is>", the missing index of a recording cut short or a truncated file named as such. */
Ros1BagLayout readRos1BagLayout(const std::string& path);

/** Why librosbag cannot read `chunk` of `file` ("" if it can): a compression other than none,
 * bz2 and lz4; a stated size past kMaxBagChunkBytes; data that does not decompress to its
 * stated size; a record inside whose header or data runs past the chunk's end or whose header
 * is damaged; an index offset not at a message record. */
std::string ros1ChunkProblem(std::ifstream& file, const Ros1Chunk& chunk);

}  // namespace swslam::io

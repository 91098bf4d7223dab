// A ROS 1 bag's records checked before librosbag reads them: bags of each compression written
// by librosbag's own writer read whole; each length, header and index damaged is named with
// its record and byte; a chunk's damage is that chunk's alone.
#include <swslam/io/ros1_bag_layout.h>

#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>

#include "test_support.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace swslam::io;
using swslam::test::errorOf;

namespace
{
constexpr int kMessages = 40;

std::string writeBag(const std::string& name, rosbag::CompressionType compression)
{
  const std::string path = (std::filesystem::temp_directory_path() / ("swslam_layout_" + name + ".bag")).string();
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  bag.setCompression(compression);
  bag.setChunkThreshold(2048);  // several chunks
  for (int k = 0; k < kMessages; k++)
  {
    sensor_msgs::LaserScan m;
    m.header.stamp = ros::Time(1000 + 0.1 * k);
    m.ranges.assign(100, 1.0f + 0.01f * k);
    bag.write("/scan", m.header.stamp, m);
  }
  return path;
}

std::string bytesOf(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeBytes(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

void putU32(std::string& bytes, size_t at, uint32_t v) { std::memcpy(&bytes[at], &v, 4); }
uint32_t getU32(const std::string& bytes, size_t at)
{
  uint32_t v;
  std::memcpy(&v, &bytes[at], 4);
  return v;
}

/** The byte of the value of field `name` in the header of the record at `pos`. */
size_t fieldAt(const std::string& bytes, size_t pos, const std::string& name)
{
  const size_t at = bytes.find(name + "=", pos + 4);
  EXPECT_LT(at, pos + 4 + getU32(bytes, pos)) << name;
  return at + name.size() + 1;
}

/** The byte of the data length of the record at `pos`. */
size_t dataLengthAt(const std::string& bytes, size_t pos) { return pos + 4 + getU32(bytes, pos); }

/** The bag `path` with `damage` done to its bytes, written beside it as `name`. */
template <class Damage>
std::string damaged(const std::string& path, const std::string& name, Damage damage)
{
  std::string bytes = bytesOf(path);
  damage(bytes);
  const std::string out = path + "." + name + ".bag";
  writeBytes(out, bytes);
  return out;
}

std::string problemOf(const std::string& path, size_t chunk)
{
  const Ros1BagLayout layout = readRos1BagLayout(path);
  std::ifstream f(path, std::ios::binary);
  return ros1ChunkProblem(f, layout.chunks.at(chunk));
}
}  // namespace

TEST(Ros1BagLayout, ABagOfEachCompressionReadsWhole)
{
  for (const auto& [name, c] : {std::pair{"none", rosbag::compression::Uncompressed},
                                std::pair{"bz2", rosbag::compression::BZ2}, std::pair{"lz4", rosbag::compression::LZ4}})
  {
    const std::string path = writeBag(name, c);
    const Ros1BagLayout layout = readRos1BagLayout(path);
    ASSERT_GE(layout.chunks.size(), 3u) << name;
    size_t messages = 0;
    std::ifstream f(path, std::ios::binary);
    for (const Ros1Chunk& chunk : layout.chunks)
    {
      EXPECT_EQ(chunk.compression, name);
      EXPECT_LE(chunk.start_ns, chunk.end_ns);
      EXPECT_EQ(ros1ChunkProblem(f, chunk), "") << name;
      messages += chunk.offsets.size();
    }
    EXPECT_EQ(messages, size_t(kMessages)) << name;
  }
}

TEST(Ros1BagLayout, ALengthPastTheBytesLeftIsNamedWithItsRecordAndByte)
{
  const std::string path = writeBag("lengths", rosbag::compression::BZ2);
  const size_t chunk = readRos1BagLayout(path).chunks.at(1).pos;
  const std::string at = "is damaged: the record at byte " + std::to_string(chunk);
  std::string e = errorOf([&] {
    readRos1BagLayout(damaged(path, "data", [&](std::string& b) { putU32(b, dataLengthAt(b, chunk), 0xFFFFFFF0); }));
  });
  EXPECT_NE(e.find(at + " (a chunk): its data states 4294967280 bytes, but "), std::string::npos) << e;
  EXPECT_NE(e.find("before the index at byte"), std::string::npos) << e;
  e = errorOf([&] { readRos1BagLayout(damaged(path, "header", [&](std::string& b) { putU32(b, chunk, 0xFFFFFFF0); })); });
  EXPECT_NE(e.find(at + ": its header states 4294967280 bytes, but "), std::string::npos) << e;
  // A header field's length past its header: ros::Header::parse would read past it.
  e = errorOf([&] { readRos1BagLayout(damaged(path, "field", [&](std::string& b) { putU32(b, chunk + 4, 0x7FFF); })); });
  EXPECT_NE(e.find(at + ": a field of its header states 32767 bytes, but its header has"), std::string::npos) << e;
  EXPECT_NE(e.find("(a damaged header)"), std::string::npos) << e;
}

TEST(Ros1BagLayout, AChunkStatingMoreThanTheBoundOrOtherThanItHoldsIsThatChunksProblem)
{
  for (const auto& [name, c] : {std::pair{"bz2", rosbag::compression::BZ2}, std::pair{"lz4", rosbag::compression::LZ4}})
  {
    const std::string path = writeBag(std::string("size_") + name, c);
    const size_t chunk = readRos1BagLayout(path).chunks.at(1).pos;
    const std::string huge = damaged(path, "huge", [&](std::string& b) { putU32(b, fieldAt(b, chunk, "size"), 0xFFFFFFF0); });
    EXPECT_EQ(problemOf(huge, 0), "");
    EXPECT_EQ(problemOf(huge, 1), "it states 4294967280 bytes uncompressed, more than the 268435456 a chunk may hold");
    EXPECT_EQ(problemOf(huge, 2), "");
    const std::string more = damaged(path, "more", [&](std::string& b) {
      const size_t at = fieldAt(b, chunk, "size");
      putU32(b, at, getU32(b, at) + 1);
    });
    EXPECT_NE(problemOf(more, 1).find(std::string("its ") + name + " data "), std::string::npos) << problemOf(more, 1);
    // Damaged compressed data.
    const std::string garbled = damaged(path, "garbled", [&](std::string& b) {
      const size_t data = dataLengthAt(b, chunk) + 4;
      for (size_t i = 20; i < 60; i++) b[data + i] = char(0x5A);
    });
    EXPECT_NE(problemOf(garbled, 1), "");
  }
}

TEST(Ros1BagLayout, ARecordInsideAChunkOrAnIndexOffsetAmissIsNamed)
{
  const std::string path = writeBag("inner", rosbag::compression::Uncompressed);
  const Ros1Chunk chunk = readRos1BagLayout(path).chunks.at(1);
  // The chunk's first record states a data length past the chunk's end.
  const std::string inner = damaged(path, "inner", [&](std::string& b) {
    putU32(b, dataLengthAt(b, chunk.data_pos), 0x00FFFFFF);
  });
  const std::string p = problemOf(inner, 1);
  EXPECT_NE(p.find("the record at byte 0 of its " + std::to_string(chunk.size) +
                   " uncompressed bytes: its data states 16777215 bytes, but"),
            std::string::npos)
      << p;
  // The chunk's first index entry off by one byte.
  const std::string offset = damaged(path, "offset", [&](std::string& b) {
    const size_t index = chunk.data_pos + chunk.data_len;  // its index data record
    const size_t entry = index + 8 + getU32(b, index);
    putU32(b, entry + 8, getU32(b, entry + 8) + 1);
  });
  EXPECT_NE(problemOf(offset, 1).find("its index places a message at byte " + std::to_string(chunk.offsets[0] + 1) +
                                      " of its uncompressed data, where no record starts"),
            std::string::npos)
      << problemOf(offset, 1);
}

TEST(Ros1BagLayout, TheIndexIsChecked)
{
  const std::string path = writeBag("index", rosbag::compression::Uncompressed);
  const Ros1BagLayout layout = readRos1BagLayout(path);
  const std::string bytes = bytesOf(path);
  const size_t info = bytes.rfind(std::string("chunk_pos=", 10));  // the last chunk info's field
  ASSERT_NE(info, std::string::npos);
  std::string e = errorOf([&] {
    readRos1BagLayout(damaged(path, "pos", [&](std::string& b) { putU32(b, info + 10, getU32(b, info + 10) + 1); }));
  });
  EXPECT_NE(e.find("where no chunk record starts"), std::string::npos) << e;
  // One connection more than there are: a chunk info stands where it should be.
  e = errorOf([&] {
    readRos1BagLayout(damaged(path, "conns", [&](std::string& b) { b[fieldAt(b, 13, "conn_count")] += 1; }));
  });
  EXPECT_NE(e.find("its index: connection 2 of 2 at byte"), std::string::npos) << e;
  EXPECT_NE(e.find("a chunk info record is there"), std::string::npos) << e;
  // One chunk fewer than there are: the index goes on past what the header states.
  e = errorOf([&] {
    readRos1BagLayout(damaged(path, "chunks", [&](std::string& b) { b[fieldAt(b, 13, "chunk_count")] -= 1; }));
  });
  EXPECT_NE(e.find("its index ends at byte"), std::string::npos) << e;
  // A message's time outside its chunk's.
  e = errorOf([&] {
    readRos1BagLayout(damaged(path, "time", [&](std::string& b) {
      const Ros1Chunk& c = layout.chunks.at(1);
      const size_t index = c.data_pos + c.data_len;
      putU32(b, index + 8 + getU32(b, index), 999);  // the first entry's seconds
    }));
  });
  EXPECT_NE(e.find("entry 1 is at time 999 s"), std::string::npos) << e;
  // Cut inside the index; no index at all.
  e = errorOf([&] { readRos1BagLayout(damaged(path, "cut", [](std::string& b) { b.resize(b.size() - 10); })); });
  EXPECT_NE(e.find("`rosbag reindex` rebuilds it"), std::string::npos) << e;
  e = errorOf([&] { readRos1BagLayout(damaged(path, "half", [](std::string& b) { b.resize(b.size() / 2); })); });
  EXPECT_NE(e.find("past its end at byte"), std::string::npos) << e;
  EXPECT_NE(e.find("a truncated bag has lost its index"), std::string::npos) << e;
}

TEST(Ros1BagLayout, AnEncryptedBagIsRefused)
{
  // librosbag would ask GnuPG for the key. The file header with one field more, its padding
  // one field shorter.
  const std::string path = writeBag("encrypted", rosbag::compression::Uncompressed);
  const std::string e = errorOf([&] {
    readRos1BagLayout(damaged(path, "encryptor", [](std::string& b) {
      const std::string field = "encryptor=rosbag/AesCbcEncryptor";
      std::string bytes(4, '\0');
      putU32(bytes, 0, uint32_t(field.size()));
      bytes += field;
      const uint32_t header_len = getU32(b, 13), data_len = getU32(b, 13 + 4 + header_len);
      b.insert(13 + 4 + header_len, bytes);
      putU32(b, 13, header_len + uint32_t(bytes.size()));
      putU32(b, 13 + 4 + header_len + bytes.size(), data_len - uint32_t(bytes.size()));
      b.erase(13 + 8 + header_len + bytes.size(), bytes.size());  // from the padding
    }));
  });
  EXPECT_NE(e.find("is encrypted (rosbag/AesCbcEncryptor): this program reads unencrypted bags"), std::string::npos)
      << e;
}

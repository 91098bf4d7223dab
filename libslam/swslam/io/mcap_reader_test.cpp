// The MCAP record reader on files laid out byte by byte: plain and chunked (none, zstd, lz4)
// messages; bad magic, truncation at every byte, lengths past the file, chunk sizes past the
// bounds, an unknown compression and a damaged CRC, each named.
#include <swslam/io/mcap_reader.h>
#include <swslam/io/ros2_test_writers.h>

#include <lz4frame.h>
#include <zlib.h>
#include <zstd.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace swslam::io;
using swslam::io::testing::McapOut;

namespace
{
std::string tempPath(const std::string& name)
{
  return (std::filesystem::temp_directory_path() / ("swslam_mcap_" + name + ".mcap")).string();
}

/** Schema 1, channel 3 on /scan, then messages "m0", "m1", "m2" at 10, 20, 30 ns. */
std::vector<uint8_t> records()
{
  McapOut r;
  r.bytes.clear();
  r.add(McapOut::schema(1, "sensor_msgs/msg/LaserScan")).add(McapOut::channel(3, 1, "/scan"));
  for (int i = 0; i < 3; i++) r.add(McapOut::message(3, 10 * (i + 1), {'m', uint8_t('0' + i)}));
  return r.bytes;
}

uint32_t crcOf(const std::vector<uint8_t>& b) { return static_cast<uint32_t>(crc32(0, b.data(), b.size())); }

std::vector<uint8_t> compressed(const std::string& compression, const std::vector<uint8_t>& b)
{
  std::vector<uint8_t> out;
  if (compression == "zstd")
  {
    out.resize(ZSTD_compressBound(b.size()));
    out.resize(ZSTD_compress(out.data(), out.size(), b.data(), b.size(), 3));
  }
  else if (compression == "lz4")
  {
    out.resize(LZ4F_compressFrameBound(b.size(), nullptr));
    out.resize(LZ4F_compressFrame(out.data(), out.size(), b.data(), b.size(), nullptr));
  }
  else
    out = b;
  return out;
}

/** The messages' payloads, and the error that ended the reading ("" if none). */
std::pair<std::vector<std::string>, std::string> readAll(const std::string& path)
{
  std::vector<std::string> got;
  try
  {
    McapReader r(path);
    McapMessage m;
    while (r.next(m))
    {
      EXPECT_EQ(r.channels().at(m.channel_id).topic, "/scan");
      got.emplace_back(m.data.begin(), m.data.end());
    }
    EXPECT_FALSE(r.next(m));
  }
  catch (const McapError& e)
  {
    return {got, e.what()};
  }
  return {got, ""};
}

const std::vector<std::string> kAll{"m0", "m1", "m2"};
}  // namespace

TEST(McapReader, ReadsPlainAndChunkedMessagesInEveryCompression)
{
  McapOut plain;
  plain.add(McapOut::header()).add(records());
  plain.write(tempPath("plain"));
  EXPECT_EQ(readAll(tempPath("plain")), std::make_pair(kAll, std::string()));

  for (const std::string c : {"", "zstd", "lz4"})
  {
    McapOut f;
    f.add(McapOut::header()).add(McapOut::chunk(c, compressed(c, records()), records().size(), crcOf(records())));
    f.write(tempPath("chunk" + c));
    EXPECT_EQ(readAll(tempPath("chunk" + c)), std::make_pair(kAll, std::string())) << c;
  }
  McapReader r(tempPath("plain"));
  McapMessage m;
  ASSERT_TRUE(r.next(m));
  EXPECT_EQ(m.log_time, 10u);
  EXPECT_EQ(r.channels().at(3).schema_name, "sensor_msgs/msg/LaserScan");
  EXPECT_EQ(r.channels().at(3).message_encoding, "cdr");
}

TEST(McapReader, BadMagicAndAMissingHeaderAreNamed)
{
  std::ofstream(tempPath("magic"), std::ios::binary) << "#ROSBAG V2.0\n";
  EXPECT_THROW(
      {
        try
        {
          McapReader r(tempPath("magic"));
        }
        catch (const McapError& e)
        {
          EXPECT_NE(std::string(e.what()).find("is not an MCAP file"), std::string::npos);
          throw;
        }
      },
      McapError);
  McapOut f;
  f.add(records());
  f.write(tempPath("noheader"));
  EXPECT_EQ(readAll(tempPath("noheader")).second,
            "MCAP record at byte 8: the file does not begin with a Header record (opcode 0x01)");
}

TEST(McapReader, AFileCutAtAnyByteGivesTheMessagesBeforeTheCutThenANamedError)
{
  for (const std::string c : {"", "zstd"})
  {
    McapOut f;
    f.add(McapOut::header());
    if (c.empty())
      f.add(records());
    else
      f.add(McapOut::chunk(c, compressed(c, records()), records().size(), crcOf(records())));
    const size_t data_end = f.bytes.size();
    f.write(tempPath("whole"));
    for (size_t n = 9; n < data_end; n++)
    {
      std::vector<uint8_t> cut(f.bytes.begin(), f.bytes.begin() + n);
      std::ofstream(tempPath("cut"), std::ios::binary).write(reinterpret_cast<const char*>(cut.data()), n);
      const auto [got, error] = readAll(tempPath("cut"));
      EXPECT_EQ(error.rfind("MCAP record at byte ", 0), 0u) << c << " cut at " << n << ": " << error;
      EXPECT_LE(got.size(), 3u);
      for (size_t i = 0; i < got.size(); i++) EXPECT_EQ(got[i], kAll[i]);
    }
  }
}

TEST(McapReader, LengthsPastTheBytesOrTheBoundsAreNamedBeforeAnyAllocation)
{
  // A record claiming 2^63 bytes.
  McapOut huge;
  huge.add(McapOut::header());
  auto r = McapOut::message(3, 1, {});
  for (int i = 0; i < 8; i++) r[1 + i] = i == 7 ? 0x80 : 0;
  huge.add(r).write(tempPath("huge"));
  EXPECT_NE(readAll(tempPath("huge")).second.find(std::string("MCAP record at byte ") +
                                                  std::to_string(McapOut::header().size() + 8) +
                                                  ": opcode 0x05 states 9223372036854775808 bytes, but the file has"),
            std::string::npos);

  // A chunk of a few bytes stating 2^63 bytes uncompressed, then 2 GiB, then 1 MiB stored
  // uncompressed in fewer bytes.
  for (const uint64_t size : {uint64_t(1) << 63, uint64_t(2) << 30, uint64_t(1) << 20})
  {
    McapOut f;
    f.add(McapOut::header()).add(McapOut::chunk(size == (1u << 20) ? "" : "zstd", compressed("zstd", records()), size, 0));
    f.write(tempPath("bigchunk"));
    const std::string e = readAll(tempPath("bigchunk")).second;
    EXPECT_NE(e.find("states " + std::to_string(size) + " bytes uncompressed, more than"), std::string::npos) << e;
  }
  // A zstd chunk stating fewer bytes than it holds.
  McapOut less;
  less.add(McapOut::header()).add(McapOut::chunk("zstd", compressed("zstd", records()), 10, 0));
  less.write(tempPath("less"));
  EXPECT_NE(readAll(tempPath("less")).second.find("cannot be decompressed: zstd: "), std::string::npos);

  // A string length past the record's end (the channel's topic).
  auto channel = McapOut::channel(3, 0, "/scan");
  channel[1 + 8 + 4] = 0xFF;  // the topic's length's low byte
  McapOut s;
  s.add(McapOut::header()).add(channel).write(tempPath("string"));
  EXPECT_EQ(readAll(tempPath("string")).second,
            "MCAP record at byte 40: a string of 255 bytes at byte 8 of its 24 runs past its end");
}

TEST(McapReader, AnUnknownCompressionADamagedCrcAndAnUndefinedChannelAreNamed)
{
  McapOut bz;
  bz.add(McapOut::header()).add(McapOut::chunk("bz2", records(), records().size(), 0)).write(tempPath("bz2"));
  EXPECT_NE(readAll(tempPath("bz2")).second.find("a Chunk compressed with 'bz2' (this reader knows zstd, lz4 and none)"),
            std::string::npos);

  McapOut crc;
  crc.add(McapOut::header()).add(McapOut::chunk("lz4", compressed("lz4", records()), records().size(), crcOf(records()) ^ 1));
  crc.write(tempPath("crc"));
  const auto [got, error] = readAll(tempPath("crc"));
  EXPECT_TRUE(got.empty());
  EXPECT_NE(error.find("(damaged data)"), std::string::npos) << error;

  McapOut orphan;
  orphan.add(McapOut::header()).add(McapOut::message(9, 1, {1})).write(tempPath("orphan"));
  EXPECT_NE(readAll(tempPath("orphan")).second.find("a Message on channel 9, not defined before it"), std::string::npos);
}

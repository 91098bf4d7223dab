// The MCAP writer read back by the MCAP reader: every message, in chunks, with its channel and
// time; the summary where the Footer places it (tests/ros2/check-ours.mjs reads our files with
// the MCAP project's own indexed reader).
#include <swslam/io/mcap_reader.h>
#include <swslam/io/mcap_writer.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace swslam::io;

TEST(McapWriter, WhatItWritesReadsBackInChunksWithASummary)
{
  const std::string path = (std::filesystem::temp_directory_path() / "swslam_mcap_writer.mcap").string();
  McapWriter w(path, "ros2", "test");
  const uint16_t schema = w.addSchema("sensor_msgs/msg/LaserScan", "ros2msg", "float32 x\n");
  const uint16_t a = w.addChannel(schema, "/a", "cdr"), b = w.addChannel(schema, "/b", "cdr", {{"k", "v"}});
  const size_t n = 3000;  // 1 KiB each: 4 chunks
  for (size_t i = 0; i < n; i++) w.write(i % 3 ? a : b, 1000 + i, std::vector<uint8_t>(1024, uint8_t(i)));
  w.close();

  McapReader r(path);
  McapMessage m;
  size_t i = 0;
  while (r.next(m))
  {
    ASSERT_LT(i, n);
    EXPECT_EQ(m.channel_id, i % 3 ? a : b);
    EXPECT_EQ(m.log_time, 1000 + i);
    EXPECT_EQ(m.data, std::vector<uint8_t>(1024, uint8_t(i)));
    i++;
  }
  EXPECT_EQ(i, n);
  EXPECT_EQ(r.channels().at(b).topic, "/b");
  EXPECT_EQ(r.channels().at(b).schema_name, "sensor_msgs/msg/LaserScan");

  // The Footer (before the closing magic) places the summary, which starts with the Schema.
  std::ifstream f(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 8u + 29u);
  const size_t footer = bytes.size() - 8 - 29;
  EXPECT_EQ(bytes[footer], 0x02);
  uint64_t summary = 0;
  for (int k = 7; k >= 0; k--) summary = (summary << 8) | uint8_t(bytes[footer + 9 + k]);
  ASSERT_LT(summary, footer);
  EXPECT_EQ(bytes[summary], 0x03);
  EXPECT_EQ(bytes.substr(bytes.size() - 8), std::string("\x89MCAP0\r\n", 8));
}

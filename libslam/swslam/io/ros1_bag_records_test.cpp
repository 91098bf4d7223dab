// One ROS 1 bag record read and checked: its lengths against the bytes there are, its header
// as ros::Header::parse reads it.
#include <swslam/io/ros1_bag_records.h>

#include <gtest/gtest.h>

#include <cstring>

using namespace swslam::io::ros1;

namespace
{
std::string u32Bytes(uint32_t v)
{
  std::string b(4, '\0');
  std::memcpy(&b[0], &v, 4);
  return b;
}
std::string fieldBytes(const std::string& f) { return u32Bytes(uint32_t(f.size())) + f; }

std::string problemOf(const std::string& bytes, Record& r)
{
  const auto read = [&](uint64_t pos, size_t n, char* out) { std::memcpy(out, bytes.data() + pos, n); };
  return readRecord(read, 0, bytes.size(), r);
}
}  // namespace

TEST(Ros1BagRecords, ARecordIsReadAndEachLengthPastTheBytesIsNamed)
{
  const std::string header = fieldBytes(std::string("op=\x05", 4)) + fieldBytes("size=abcd");
  const std::string record = u32Bytes(uint32_t(header.size())) + header + u32Bytes(3) + "xyz";
  Record r;
  EXPECT_EQ(problemOf(record, r), "");
  EXPECT_EQ(r.op, kOpChunk);
  EXPECT_EQ(r.fields.at("size"), "abcd");
  EXPECT_EQ(r.data_pos, record.size() - 3);
  EXPECT_EQ(r.end(), record.size());
  EXPECT_EQ(problemOf(record.substr(0, record.size() - 1), r), "its data states 3 bytes, but 2 are left");
  EXPECT_EQ(problemOf(u32Bytes(0xFFFFFFF0) + header, r), "its header states 4294967280 bytes, but " +
                                                             std::to_string(header.size()) + " are left");
  EXPECT_EQ(problemOf("ab", r), "only 2 bytes are left, too few for a record");
}

TEST(Ros1BagRecords, AHeaderIsCheckedAsRosReadsIt)
{
  Fields f;
  const std::string past = u32Bytes(100) + "op=x";
  EXPECT_EQ(parseHeader(past.data(), uint32_t(past.size()), f),
            "a field of its header states 100 bytes, but its header has 4 left (a damaged header)");
  const std::string no_equals = fieldBytes("opx");
  EXPECT_EQ(parseHeader(no_equals.data(), uint32_t(no_equals.size()), f),
            "a field of its header has no '=' (\"opx\": a damaged header)");
  const std::string cut = fieldBytes("a=b") + std::string("\x01\x00", 2);
  EXPECT_EQ(parseHeader(cut.data(), uint32_t(cut.size()), f), "its header ends inside a field's length (2 bytes left)");
  Record r;
  EXPECT_EQ(problemOf(u32Bytes(7) + fieldBytes("ab=") + u32Bytes(0), r),
            "its header has no op field of 1 byte (a damaged header)");
  EXPECT_EQ(opName(kOpChunkInfo), "chunk info");
  EXPECT_EQ(opName(0x2a), "op 0x2a");
}

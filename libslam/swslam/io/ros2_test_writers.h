#pragma once
// Test-only writers of MCAP records, byte by byte as the specification lays them out, to craft
// damaged files for the unit tests of the ROS 2 readers (the messages' CDR: ros2_messages.h;
// the whole-program tests also read bags written by the npm packages @mcap/core and
// @foxglove/cdr: tests/ros2/make-bags.mjs).

#include <swslam/io/ros2_messages.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace swslam::io::testing
{
/** Little-endian MCAP fields and records. */
struct McapOut
{
  std::vector<uint8_t> bytes{0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

  template <class T>
  static void put(std::vector<uint8_t>& out, T v)
  {
    for (size_t i = 0; i < sizeof(T); i++) out.push_back(uint8_t(uint64_t(v) >> (8 * i)));
  }
  static void str(std::vector<uint8_t>& out, const std::string& s)
  {
    put<uint32_t>(out, static_cast<uint32_t>(s.size()));
    out.insert(out.end(), s.begin(), s.end());
  }
  /** A record: opcode, u64 length, body. */
  static std::vector<uint8_t> record(uint8_t opcode, const std::vector<uint8_t>& body)
  {
    std::vector<uint8_t> r{opcode};
    put<uint64_t>(r, body.size());
    r.insert(r.end(), body.begin(), body.end());
    return r;
  }
  static std::vector<uint8_t> header()
  {
    std::vector<uint8_t> b;
    str(b, "ros2");
    str(b, "swslam test");
    return record(0x01, b);
  }
  static std::vector<uint8_t> schema(uint16_t id, const std::string& name)
  {
    std::vector<uint8_t> b;
    put<uint16_t>(b, id);
    str(b, name);
    str(b, "ros2msg");
    str(b, "");
    return record(0x03, b);
  }
  static std::vector<uint8_t> channel(uint16_t id, uint16_t schema, const std::string& topic)
  {
    std::vector<uint8_t> b;
    put<uint16_t>(b, id);
    put<uint16_t>(b, schema);
    str(b, topic);
    str(b, "cdr");
    put<uint32_t>(b, 0);  // metadata: no entries
    return record(0x04, b);
  }
  static std::vector<uint8_t> message(uint16_t channel, uint64_t time_ns, const std::vector<uint8_t>& data)
  {
    std::vector<uint8_t> b;
    put<uint16_t>(b, channel);
    put<uint32_t>(b, 0);
    put<uint64_t>(b, time_ns);
    put<uint64_t>(b, time_ns);
    b.insert(b.end(), data.begin(), data.end());
    return record(0x05, b);
  }
  /** A Chunk of `records` stored as `stored` with `compression`, stating `size` and `crc`. */
  static std::vector<uint8_t> chunk(const std::string& compression, const std::vector<uint8_t>& stored, uint64_t size,
                                    uint32_t crc)
  {
    std::vector<uint8_t> b;
    put<uint64_t>(b, 0);
    put<uint64_t>(b, 0);
    put<uint64_t>(b, size);
    put<uint32_t>(b, crc);
    str(b, compression);
    put<uint64_t>(b, stored.size());
    b.insert(b.end(), stored.begin(), stored.end());
    return record(0x06, b);
  }
  static std::vector<uint8_t> dataEnd() { return record(0x0F, {0, 0, 0, 0}); }

  McapOut& add(const std::vector<uint8_t>& r)
  {
    bytes.insert(bytes.end(), r.begin(), r.end());
    return *this;
  }
  /** Ends the data section (DataEnd, a Footer, the magic) and writes the file. */
  void write(const std::string& path, bool finish = true)
  {
    if (finish)
    {
      add(dataEnd());
      std::vector<uint8_t> footer(20, 0);
      add(record(0x02, footer));
      add({0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'});
    }
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  }
};

}  // namespace swslam::io::testing

#pragma once
// Test-only writers of CDR messages and MCAP records, byte by byte as the specifications lay
// them out, for the unit tests of the ROS 2 readers (the whole-program tests read bags written
// by the npm packages @mcap/core and @foxglove/cdr: tests/ros2/make-bags.mjs).

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

namespace swslam::io::testing
{
/** CDR (XCDR1) of either byte order: the 4-byte header, then aligned primitives. */
class CdrOut
{
 public:
  explicit CdrOut(bool big_endian) : big_(big_endian), bytes_{0, uint8_t(big_endian ? 0 : 1), 0, 0} {}
  template <class T>
  CdrOut& put(T v)
  {
    while ((bytes_.size() - 4) % sizeof(T)) bytes_.push_back(0);
    uint8_t b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    for (size_t i = 0; i < sizeof(T); i++) bytes_.push_back(b[big_ ? sizeof(T) - 1 - i : i]);
    return *this;
  }
  CdrOut& str(const std::string& s)
  {
    put<uint32_t>(static_cast<uint32_t>(s.size() + 1));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
    bytes_.push_back(0);
    return *this;
  }
  CdrOut& header(const std_msgs::Header& h)
  {
    put<int32_t>(static_cast<int32_t>(h.stamp.sec)).put<uint32_t>(h.stamp.nsec);
    return str(h.frame_id);
  }
  CdrOut& floats(const std::vector<float>& v)
  {
    put<uint32_t>(static_cast<uint32_t>(v.size()));
    for (float x : v) put<float>(x);
    return *this;
  }
  std::vector<uint8_t>& bytes() { return bytes_; }

 private:
  bool big_;
  std::vector<uint8_t> bytes_;
};

inline std::vector<uint8_t> laserScanCdr(const sensor_msgs::LaserScan& m, bool big_endian = false)
{
  CdrOut c(big_endian);
  c.header(m.header);
  for (float v : {m.angle_min, m.angle_max, m.angle_increment, m.time_increment, m.scan_time, m.range_min, m.range_max})
    c.put<float>(v);
  return c.floats(m.ranges).floats(m.intensities).bytes();
}

inline std::vector<uint8_t> odometryCdr(const nav_msgs::Odometry& m, bool big_endian = false)
{
  CdrOut c(big_endian);
  c.header(m.header).str(m.child_frame_id);
  const auto& p = m.pose.pose;
  for (double v : {p.position.x, p.position.y, p.position.z, p.orientation.x, p.orientation.y, p.orientation.z,
                   p.orientation.w})
    c.put<double>(v);
  for (double v : m.pose.covariance) c.put<double>(v);
  const auto& t = m.twist.twist;
  for (double v : {t.linear.x, t.linear.y, t.linear.z, t.angular.x, t.angular.y, t.angular.z}) c.put<double>(v);
  for (double v : m.twist.covariance) c.put<double>(v);
  return c.bytes();
}

inline std::vector<uint8_t> tfMessageCdr(const tf2_msgs::TFMessage& m, bool big_endian = false)
{
  CdrOut c(big_endian);
  c.put<uint32_t>(static_cast<uint32_t>(m.transforms.size()));
  for (const auto& t : m.transforms)
  {
    c.header(t.header).str(t.child_frame_id);
    const auto& tr = t.transform;
    for (double v : {tr.translation.x, tr.translation.y, tr.translation.z, tr.rotation.x, tr.rotation.y,
                     tr.rotation.z, tr.rotation.w})
      c.put<double>(v);
  }
  return c.bytes();
}

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

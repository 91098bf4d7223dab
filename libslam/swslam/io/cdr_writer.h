#pragma once
// CDR (XCDR1, as ROS 2 serializes its messages) written: the 4-byte encapsulation header of
// either byte order, then primitives each aligned to its own size (from the end of the header),
// strings with their length and NUL, sequences with their count. The counterpart of
// cdr_reader.h; ros2_messages.h writes the three messages swslam reads with it.

#include <std_msgs/Header.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace swslam::io
{
class CdrWriter
{
 public:
  explicit CdrWriter(bool big_endian = false) : big_(big_endian), bytes_{0, uint8_t(big_endian ? 0 : 1), 0, 0} {}

  template <class T>
  CdrWriter& put(T v)
  {
    while ((bytes_.size() - 4) % sizeof(T)) bytes_.push_back(0);
    uint8_t b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    for (size_t i = 0; i < sizeof(T); i++) bytes_.push_back(b[big_ ? sizeof(T) - 1 - i : i]);
    return *this;
  }
  CdrWriter& str(const std::string& s);
  /** A std_msgs/msg/Header: its stamp (int32 sec, uint32 nanosec) and frame id. */
  CdrWriter& header(const std_msgs::Header& h);
  /** A float32 sequence. */
  CdrWriter& floats(const std::vector<float>& v);
  std::vector<uint8_t>& bytes() { return bytes_; }

 private:
  bool big_;
  std::vector<uint8_t> bytes_;
};

}  // namespace swslam::io

#include <swslam/io/cdr_writer.h>

namespace swslam::io
{
CdrWriter& CdrWriter::str(const std::string& s)
{
  put<uint32_t>(static_cast<uint32_t>(s.size() + 1));
  bytes_.insert(bytes_.end(), s.begin(), s.end());
  bytes_.push_back(0);
  return *this;
}

CdrWriter& CdrWriter::header(const std_msgs::Header& h)
{
  put<int32_t>(static_cast<int32_t>(h.stamp.sec)).put<uint32_t>(h.stamp.nsec);
  return str(h.frame_id);
}

CdrWriter& CdrWriter::floats(const std::vector<float>& v)
{
  put<uint32_t>(static_cast<uint32_t>(v.size()));
  for (float x : v) put<float>(x);
  return *this;
}

}  // namespace swslam::io

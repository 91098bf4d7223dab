#include <swslam/io/read_progress.h>

#include <swslam/io/gzip_file.h>

#include <algorithm>
#include <fstream>

namespace swslam::io
{
double gzipFraction(uint64_t position, uint64_t isize)
{
  constexpr uint64_t kWrap = uint64_t(1) << 32;
  uint64_t total = isize;
  if (position > total) total += (position - total + kWrap - 1) / kWrap * kWrap;
  return total == 0 ? 1.0 : std::min(1.0, static_cast<double>(position) / static_cast<double>(total));
}

ReadProgress::ReadProgress(const std::string& path)
{
  requireLogFile(path);
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return;
  file_size_ = static_cast<uint64_t>(in.tellg());
  unsigned char magic[2] = {0, 0}, trailer[4] = {0, 0, 0, 0};
  in.seekg(0);
  in.read(reinterpret_cast<char*>(magic), 2);
  if (!in || magic[0] != 0x1f || magic[1] != 0x8b || file_size_ < 18) return;  // 18: the smallest gzip file
  in.seekg(static_cast<std::streamoff>(file_size_ - 4));
  in.read(reinterpret_cast<char*>(trailer), 4);
  if (!in) return;
  gzip_ = true;
  isize_ = uint64_t(trailer[0]) | uint64_t(trailer[1]) << 8 | uint64_t(trailer[2]) << 16 | uint64_t(trailer[3]) << 24;
}

double ReadProgress::fraction(uint64_t uncompressed_position) const
{
  if (gzip_) return gzipFraction(uncompressed_position, isize_);
  return file_size_ == 0 ? 1.0
                         : std::min(1.0, static_cast<double>(uncompressed_position) / static_cast<double>(file_size_));
}

}  // namespace swslam::io

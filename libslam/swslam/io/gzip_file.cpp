#include <swslam/io/gzip_file.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <limits>
#include <zlib.h>

namespace swslam::io
{
void requireLogFile(const std::string& path)
{
  std::error_code ec;
  const auto type = std::filesystem::status(path, ec).type();
  if (type == std::filesystem::file_type::fifo || type == std::filesystem::file_type::socket ||
      type == std::filesystem::file_type::character || type == std::filesystem::file_type::block)
    throw std::runtime_error("'" + path + "' is not a file but a pipe, socket or device: give a log file");
}

GzipFile::GzipFile(const std::string& path) : path_(path)
{
  requireLogFile(path);
  file_ = gzopen(path.c_str(), "rb");
  if (!file_) throw std::runtime_error("cannot open '" + path + "': " + std::strerror(errno));
  gzbuffer(file_, 1 << 16);
}

GzipFile::~GzipFile() { gzclose(file_); }

size_t GzipFile::read(void* buf, size_t len)
{
  size_t got = 0;
  while (got < len)
  {
    const unsigned ask = static_cast<unsigned>(std::min<size_t>(len - got, std::numeric_limits<int>::max()));
    const int n = gzread(file_, static_cast<char*>(buf) + got, ask);
    if (n > 0)
    {
      got += static_cast<size_t>(n);
      position_ += static_cast<uint64_t>(n);
      continue;
    }
    int code = Z_OK;
    const char* message = gzerror(file_, &code);
    if (n == 0 && code == Z_OK) break;  // the end of the content
    if (got > 0) break;                 // returned first; the error comes again next time
    const std::string after = " after " + std::to_string(position_) + " bytes of content";
    if (code == Z_BUF_ERROR)
      throw GzipError("the gzip stream is cut short" + after + " (a truncated file)", position_);
    if (code == Z_ERRNO) throw GzipError("read error" + after + ": " + std::strerror(errno), position_);
    throw GzipError("corrupt gzip data" + after + " (zlib: " + message + ")", position_);
  }
  return got;
}

}  // namespace swslam::io

#include <swslam/common/gzip_output.h>

#include <swslam/common/atomic_file.h>

#include <stdexcept>
#include <vector>

#include <zlib.h>

namespace swslam::common
{
struct GzipOutput::State
{
  z_stream z{};
  std::vector<unsigned char> buffer = std::vector<unsigned char>(1 << 16);
  bool finished = false;
};

GzipOutput::GzipOutput(std::ostream& out, int level) : state_(std::make_unique<State>()), out_(out)
{
  if (level < 0 || level > 9) throw std::invalid_argument("gzip: level " + std::to_string(level) + " is not 0-9");
  // windowBits 15 + 16: the gzip format (header and CRC trailer), as gzip and MRPT read it.
  if (deflateInit2(&state_->z, level, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("gzip: zlib could not start");
}

GzipOutput::~GzipOutput() { deflateEnd(&state_->z); }

void GzipOutput::deflateAll(int flush)
{
  z_stream& z = state_->z;
  int result = Z_OK;
  do
  {
    z.next_out = state_->buffer.data();
    z.avail_out = static_cast<uInt>(state_->buffer.size());
    result = deflate(&z, flush);
    if (result == Z_STREAM_ERROR) throw std::runtime_error("gzip: zlib failed");
    out_.write(reinterpret_cast<const char*>(state_->buffer.data()),
               static_cast<std::streamsize>(state_->buffer.size() - z.avail_out));
    if (!out_) throw std::runtime_error(streamFailure());
  } while (z.avail_out == 0 || (flush == Z_FINISH && result != Z_STREAM_END));
}

size_t GzipOutput::Write(const void* buffer, size_t count)
{
  if (state_->finished) throw std::logic_error("gzip: written after finish()");
  z_stream& z = state_->z;
  const auto* in = static_cast<const unsigned char*>(buffer);
  for (size_t left = count; left > 0;)  // in pieces zlib's uInt counts
  {
    const uInt piece = static_cast<uInt>(std::min<size_t>(left, 1u << 30));
    z.next_in = const_cast<unsigned char*>(in + (count - left));
    z.avail_in = piece;
    deflateAll(Z_NO_FLUSH);
    left -= piece;
  }
  written_ += count;
  return count;
}

void GzipOutput::finish()
{
  if (state_->finished) return;
  state_->z.avail_in = 0;
  deflateAll(Z_FINISH);
  state_->finished = true;
}

size_t GzipOutput::Read(void*, size_t) { throw std::logic_error("gzip: the output cannot be read"); }

uint64_t GzipOutput::Seek(int64_t, CStream::TSeekOrigin) { throw std::logic_error("gzip: the output cannot seek"); }

void writeGzipAtomically(const std::string& path, int level, const std::function<void(mrpt::io::CStream& out)>& write)
{
  writeStreamAtomically(path, [&](std::ostream& file) {
    GzipOutput gz(file, level);
    write(gz);
    gz.finish();
  });
}

}  // namespace swslam::common

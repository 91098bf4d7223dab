#pragma once
// Writing gzip files whose every byte is checked: MRPT's CFileGZOutputStream ignores what
// gzclose() returns, so the last block of a file written as the disk filled up was lost
// without a word (a short map.gridmap.gz, rawlog). Here the compressed bytes go through a
// checked file stream (writeStreamAtomically).

#include <mrpt/io/CStream.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace swslam::common
{
/** An MRPT stream that gzip-compresses what is written to it into `out` (zlib, gzip format).
 * A write that `out` refuses throws std::runtime_error (streamFailure()); finish() writes the
 * end of the stream and must be called once the data is all written. Not readable. */
class GzipOutput : public mrpt::io::CStream
{
 public:
  GzipOutput(std::ostream& out, int level);
  ~GzipOutput() override;
  GzipOutput(const GzipOutput&) = delete;
  GzipOutput& operator=(const GzipOutput&) = delete;

  size_t Write(const void* buffer, size_t count) override;
  void finish();

  size_t Read(void*, size_t) override;
  uint64_t Seek(int64_t, CStream::TSeekOrigin = sFromBeginning) override;
  uint64_t getTotalBytesCount() const override { return written_; }
  uint64_t getPosition() const override { return written_; }

 private:
  /** Runs deflate with `flush` until it has taken all its input, writing what it gives out. */
  void deflateAll(int flush);

  struct State;
  std::unique_ptr<State> state_;
  std::ostream& out_;
  uint64_t written_ = 0;
};

/** Writes a gzip file (compression `level`, 0-9) atomically: `write` writes the content into
 * the stream; every compressed byte is checked to have reached the disk. */
void writeGzipAtomically(const std::string& path, int level, const std::function<void(mrpt::io::CStream& out)>& write);

}  // namespace swslam::common

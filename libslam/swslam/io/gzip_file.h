#pragma once
// Reading a file that may be gzip-compressed (or plain, read as is), telling a damaged
// compressed stream from its end. MRPT's CFileGZInputStream reported a truncated .gz file as
// a clean end (a CARMEN log cut in half converted half its scans, exit 0) and a corrupt one as
// a read of 2^64-1 bytes.

#include <cstdint>
#include <stdexcept>
#include <string>

struct gzFile_s;

namespace swslam::io
{
/** The compressed stream is damaged: cut short, or corrupt. What was read before is the
 * file's content up to `contentRead()` bytes (after a bit flip, possibly with damaged bytes
 * shortly before). */
class GzipError : public std::runtime_error
{
 public:
  GzipError(const std::string& what, uint64_t content_read) : std::runtime_error(what), read_(content_read) {}
  uint64_t contentRead() const { return read_; }

 private:
  uint64_t read_;
};

/** Throws std::runtime_error "'<path>' is not a file but a pipe, socket or device: give a log
 * file" if `path` is one: a FIFO without a writer blocks its open for ever (a signal does not
 * end it), and the readers open a log more than once (to tell its format, its size, its
 * stamps). Every reader checks it before opening (GzipFile, ReadProgress, openScanSource). */
void requireLogFile(const std::string& path);

class GzipFile
{
 public:
  /** Opens `path`. Throws std::runtime_error if it cannot be opened, or is a pipe, socket or
   * device (requireLogFile). */
  explicit GzipFile(const std::string& path);
  ~GzipFile();
  GzipFile(const GzipFile&) = delete;
  GzipFile& operator=(const GzipFile&) = delete;

  /** Up to `len` bytes of the content; fewer only at its end (0 after it). Throws GzipError
   * saying how many content bytes were read (the caller names the file) when the compressed stream is cut
   * short or corrupt, and on every later call. */
  size_t read(void* buf, size_t len);
  /** Content bytes read so far (the position in the uncompressed stream). */
  uint64_t position() const { return position_; }

 private:
  std::string path_;
  gzFile_s* file_ = nullptr;
  uint64_t position_ = 0;
};

}  // namespace swslam::io

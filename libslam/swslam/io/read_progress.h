#pragma once
// How much of a log file has been read, for progress bars. MRPT's CFileGZInputStream reports
// its position in the uncompressed stream but the file's compressed size, so their ratio
// reached 100% a third of the way through a gzip rawlog. The uncompressed size of a gzip
// file is in its trailer, modulo 2^32 (ISIZE).

#include <cstdint>
#include <string>

namespace swslam::io
{
/** The fraction read at uncompressed position `position` of a gzip stream whose trailer
 * holds `isize` (the uncompressed size modulo 2^32): against the smallest size congruent to
 * `isize` that is at least `position`, clamped to [0, 1]. Exact below 4 GiB uncompressed;
 * beyond, an estimate that never passes 1 before the end. */
double gzipFraction(uint64_t position, uint64_t isize);

class ReadProgress
{
 public:
  /** Reads the file's size and, for a gzip file, its trailer. Never throws: an unreadable file
   * gives a fraction of 1. */
  explicit ReadProgress(const std::string& path);
  /** The fraction read at `uncompressed_position` (CFileGZInputStream::getPosition()). */
  double fraction(uint64_t uncompressed_position) const;

 private:
  uint64_t file_size_ = 0;
  bool gzip_ = false;
  uint64_t isize_ = 0;
};

}  // namespace swslam::io

#pragma once
// A file compressed whole with zstd (rosbag2's compression_mode FILE: bag_0.db3.zstd)
// decompressed into another file, streaming, with its size bounded: a damaged or hostile frame
// cannot fill the disk.

#include <cstdint>
#include <string>

namespace swslam::io
{
/** [bytes] The largest file decompressed (16 GiB: rosbag2 splits its recordings into files far
 * smaller; a recording that large would be read from an uncompressed copy). */
constexpr uint64_t kMaxZstdFileBytes = uint64_t(16) << 30;

/** Decompresses the zstd file `from` into `to`, 1 MiB at a time. Throws std::runtime_error
 * naming the problem, and leaves no `to`: `from` not zstd, damaged or cut short, more than
 * `max_bytes` or 32768 times its own size (zstd's largest expansion) decompressed, or `to`
 * not written (a full disk). */
void decompressZstdFile(const std::string& from, const std::string& to, uint64_t max_bytes = kMaxZstdFileBytes);

}  // namespace swslam::io

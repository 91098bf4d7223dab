#pragma once
// Images written whole or not at all: apart from atomic_file.h so that the programs that
// write no image do not load MRPT's image library (tests/startup_test.sh).

#include <string>

namespace mrpt::img
{
class CImage;
}

namespace swslam::common
{
/** Writes the image to `path` atomically, in the format of its extension (PNG...), and reads
 * it back: the image libraries ignore an error when they close the file, so a short file
 * (the disk full) is found by decoding it, and is an error naming the cause. */
void writeImageAtomically(const std::string& path, const mrpt::img::CImage& image);

}  // namespace swslam::common

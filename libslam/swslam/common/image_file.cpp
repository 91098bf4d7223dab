#include <swslam/common/image_file.h>

#include <swslam/common/atomic_file.h>

#include <mrpt/img/CImage.h>

#include <cerrno>
#include <stdexcept>

namespace swslam::common
{
void writeImageAtomically(const std::string& path, const mrpt::img::CImage& image)
{
  writeAtomically(path, [&](const std::string& tmp) {
    errno = 0;
    const bool saved = image.saveToFile(tmp);
    const std::string why = streamFailure();  // the save's, before the reading changes errno
    if (!saved) throw std::runtime_error("cannot save the image: " + why);
    mrpt::img::CImage back;
    if (!back.loadFromFile(tmp) || back.getWidth() != image.getWidth() || back.getHeight() != image.getHeight())
      throw std::runtime_error("the image written does not read back whole (" + why + ")");
  });
}

}  // namespace swslam::common

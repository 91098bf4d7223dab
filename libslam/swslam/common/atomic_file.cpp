#include <swslam/common/atomic_file.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace swslam::common
{
namespace fs = std::filesystem;

namespace
{
/** Where writeAtomically() writes `path` before renaming it, in the same folder. */
std::string atomicTemporaryPath(const std::string& path)
{
  const fs::path final_path(path);
  // Keep the final extension last: some writers (MRPT, image codecs) pick the format from it.
  const std::string tmp_name = "." + final_path.stem().string() + ".tmp" +
                               std::to_string(::getpid()) + final_path.extension().string();
  return (final_path.parent_path() / tmp_name).string();
}
}  // namespace

bool isAtomicTemporary(const std::string& file_name)
{
  static const std::regex pattern(R"(^\..+\.tmp[0-9]+(\.[^.]+)*$)");
  return std::regex_match(file_name, pattern);
}

void writeAtomically(const std::string& path,
                     const std::function<void(const std::string& tmp_path)>& writer)
{
  const fs::path final_path(path);
  const fs::path tmp = atomicTemporaryPath(path);
  try
  {
    writer(tmp.string());
    if (!fs::exists(tmp)) throw std::runtime_error("nothing was written");
    fs::rename(tmp, final_path);
  }
  catch (const std::exception& e)
  {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw std::runtime_error("cannot write '" + path + "': " + e.what());
  }
}

std::string streamFailure()
{
  return std::string("the disk refused the data: ") + (errno != 0 ? std::strerror(errno) : "write error");
}

void writeStreamAtomically(const std::string& path, const std::function<void(std::ostream& out)>& write)
{
  writeAtomically(path, [&](const std::string& tmp) {
    errno = 0;
    std::ofstream f(tmp, std::ios::binary);
    if (!f) throw std::runtime_error("cannot create '" + tmp + "': " + std::strerror(errno));
    write(f);
    // The last buffered bytes go out here: a full disk often shows only now.
    f.close();
    if (!f) throw std::runtime_error(streamFailure());
  });
}

void writeTextAtomically(const std::string& path, const std::string& content)
{
  writeStreamAtomically(path, [&](std::ostream& out) { out << content; });
}

}  // namespace swslam::common

#include <swslam/common/atomic_file.h>

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

void writeTextAtomically(const std::string& path, const std::string& content)
{
  writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream f(tmp, std::ios::binary);
    if (!f) throw std::runtime_error("cannot create '" + tmp + "'");
    f << content;
    f.close();
    if (!f) throw std::runtime_error("write error on '" + tmp + "'");
  });
}

}  // namespace swslam::common

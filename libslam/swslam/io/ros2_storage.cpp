#include <swslam/io/ros2_storage.h>

#include <swslam/io/mcap_reader.h>
#include <swslam/io/zstd_file.h>

#include <yaml-cpp/yaml.h>
#include <zstd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>

namespace swslam::io
{
namespace
{
namespace fs = std::filesystem;

bool endsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

struct Layout
{
  std::vector<std::string> files;
  bool mcap = false;
  bool message_zstd = false;
  bool file_zstd = false;
};

/** A folder of this process's under $TMPDIR (or /tmp), removed with all it holds. */
struct ScratchFolder
{
  std::string path;
  ScratchFolder()
  {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/swslam-rosbag2-XXXXXX";
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a folder " + pattern);
    path = pattern;
  }
  ~ScratchFolder()
  {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

/** The files of a bag compressed file by file, decompressed into `scratch` (their names
 * without .zstd). */
std::vector<std::string> decompressed(const std::vector<std::string>& files, const ScratchFolder& scratch)
{
  std::vector<std::string> out;
  for (const std::string& f : files)
  {
    std::string name = fs::path(f).filename().string();
    if (endsWith(name, ".zstd")) name.resize(name.size() - 5);
    out.push_back((fs::path(scratch.path) / name).string());
    decompressZstdFile(f, out.back());
  }
  return out;
}

/** metadata.yaml of the rosbag2 folder `dir`. */
Layout readMetadata(const std::string& dir)
{
  const std::string path = (fs::path(dir) / "metadata.yaml").string();
  Layout layout;
  try
  {
    const YAML::Node info = YAML::LoadFile(path)["rosbag2_bagfile_information"];
    if (!info || !info.IsMap()) throw std::runtime_error("it has no map rosbag2_bagfile_information");
    const std::string storage = info["storage_identifier"].as<std::string>("");
    if (storage != "sqlite3" && storage != "mcap")
      throw std::runtime_error("storage_identifier '" + storage + "' (this program reads sqlite3 and mcap)");
    layout.mcap = storage == "mcap";
    const std::string format = info["compression_format"].as<std::string>("");
    const std::string mode = info["compression_mode"].as<std::string>("");
    if (!format.empty() && format != "zstd") throw std::runtime_error("compression_format '" + format + "' (not zstd)");
    if (!format.empty() && mode != "FILE" && mode != "MESSAGE")
      throw std::runtime_error("compression_mode '" + mode + "' (FILE or MESSAGE)");
    layout.message_zstd = format == "zstd" && mode == "MESSAGE";
    layout.file_zstd = format == "zstd" && mode == "FILE";
    const YAML::Node files = info["relative_file_paths"];
    if (!files || !files.IsSequence() || files.size() == 0) throw std::runtime_error("it lists no relative_file_paths");
    for (const YAML::Node& f : files)
    {
      const fs::path name(f.as<std::string>());
      if (name.is_absolute() || std::find(name.begin(), name.end(), "..") != name.end())
        throw std::runtime_error("its file '" + name.string() + "' is not inside the folder");
      // Early rosbag2 releases wrote the folder's name before the file's.
      fs::path file = fs::path(dir) / name;
      if (!fs::exists(file)) file = fs::path(dir) / name.filename();
      if (!fs::is_regular_file(file)) throw std::runtime_error("its file '" + name.string() + "' is missing");
      layout.files.push_back(file.string());
    }
  }
  catch (const YAML::Exception& e)
  {
    throw std::runtime_error("rosbag2 '" + dir + "': metadata.yaml cannot be read: " + e.what());
  }
  catch (const std::runtime_error& e)
  {
    throw std::runtime_error("rosbag2 '" + dir + "': metadata.yaml: " + e.what());
  }
  return layout;
}

}  // namespace

std::vector<uint8_t> unzstdMessage(const std::vector<uint8_t>& in)
{
  const unsigned long long n = ZSTD_getFrameContentSize(in.data(), in.size());
  if (n == ZSTD_CONTENTSIZE_ERROR) throw std::runtime_error("a message compressed with zstd is not a zstd frame");
  if (n == ZSTD_CONTENTSIZE_UNKNOWN || n > kMaxRos2MessageBytes || n > mcapExpansionBound("zstd", in.size()))
    throw std::runtime_error("a zstd-compressed message of " + std::to_string(in.size()) + " bytes states " +
                             (n == ZSTD_CONTENTSIZE_UNKNOWN ? std::string("no size") : std::to_string(n) + " bytes") +
                             " (at most " + std::to_string(kMaxRos2MessageBytes) + ")");
  std::vector<uint8_t> out(n);
  const size_t got = ZSTD_decompress(out.data(), out.size(), in.data(), in.size());
  if (ZSTD_isError(got) || got != n)
    throw std::runtime_error(std::string("a zstd-compressed message cannot be decompressed: ") +
                             (ZSTD_isError(got) ? ZSTD_getErrorName(got) : "shorter than stated"));
  return out;
}

std::vector<BagTopic> sortedTopics(std::map<std::string, BagTopic> by_name)
{
  std::vector<BagTopic> out;
  for (auto& [name, t] : by_name) out.push_back(std::move(t));
  return out;
}

std::unique_ptr<Ros2Storage> openRos2Storage(const std::string& path)
{
  if (fs::is_directory(path))
  {
    if (!fs::is_regular_file(fs::path(path) / "metadata.yaml"))
      throw std::runtime_error("'" + path + "' is a folder without metadata.yaml: not a rosbag2 bag");
    Layout layout = readMetadata(path);
    std::shared_ptr<ScratchFolder> scratch;
    if (layout.file_zstd)
    {
      scratch = std::make_shared<ScratchFolder>();
      layout.files = decompressed(layout.files, *scratch);
    }
    std::unique_ptr<Ros2Storage> storage;
    if (layout.mcap)
      storage = openMcapFiles(layout.files, layout.message_zstd);
    else
      storage = openDb3Files(layout.files, layout.message_zstd);
    storage->keep(scratch);
    return storage;
  }
  if (!fs::is_regular_file(path)) throw std::runtime_error("cannot open bag '" + path + "': no such file");
  if (endsWith(path, ".db3")) return openDb3Files({path}, false);
  return openMcapFiles({path}, false);
}

bool isRos2Bag(const std::string& path)
{
  std::error_code ec;
  if (fs::is_directory(path, ec)) return fs::is_regular_file(fs::path(path) / "metadata.yaml", ec);
  return endsWith(path, ".mcap") || endsWith(path, ".db3") || hasMcapMagic(path);
}

}  // namespace swslam::io

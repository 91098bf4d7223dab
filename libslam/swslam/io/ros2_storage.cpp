#include <swslam/io/ros2_storage.h>

#include <swslam/io/mcap_reader.h>
#include <swslam/io/zstd_file.h>

#include <sqlite3.h>
#include <yaml-cpp/yaml.h>
#include <zstd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

namespace swslam::io
{
namespace
{
namespace fs = std::filesystem;

bool endsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/** A message compressed with zstd (rosbag2's compression_mode MESSAGE), decompressed; its
 * size as its frame states it, bounded. */
std::vector<uint8_t> unzstd(const std::vector<uint8_t>& in)
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

/** Topic counts by name, as a sorted topic list. */
std::vector<BagTopic> sortedTopics(std::map<std::string, BagTopic> by_name)
{
  std::vector<BagTopic> out;
  for (auto& [name, t] : by_name) out.push_back(std::move(t));
  return out;
}

class McapStorage : public Ros2Storage
{
 public:
  McapStorage(std::vector<std::string> files, bool message_zstd) : files_(std::move(files)), zstd_(message_zstd)
  {
    std::map<std::string, BagTopic> by_name;
    auto addChannels = [&] {
      for (const auto& [id, c] : reader_->channels())
      {
        BagTopic& t = by_name[c.topic];
        t.name = c.topic;
        t.type = c.schema_name;
      }
    };
    McapMessage m;
    std::string problem;  // a damaged file: counted up to it, reported when read
    for (file_ = 0; file_ < files_.size(); file_++)
    {
      reader_.reset();
      try
      {
        reader_ = std::make_unique<McapReader>(files_[file_]);
        while (reader_->next(m)) by_name[reader_->channels().at(m.channel_id).topic].messages++;
        addChannels();
      }
      catch (const std::runtime_error& e)
      {
        if (!reader_) throw std::runtime_error(inFile(e.what()));  // not an MCAP file
        addChannels();
        problem = e.what();
        break;
      }
    }
    if (by_name.empty() && !problem.empty())  // damaged before its first channel
      throw std::runtime_error("cannot read '" + files_[file_] + "': " + problem);
    topics_ = sortedTopics(by_name);
    select({});
  }

  void select(const std::vector<std::string>& topics) override
  {
    selected_ = std::set<std::string>(topics.begin(), topics.end());
    file_ = 0;
    reader_.reset();
  }

  bool next(Ros2Message& out) override
  {
    try
    {
      return nextOfFiles(out);
    }
    catch (const McapError& e)
    {
      throw std::runtime_error(inFile(e.what()));
    }
  }

 private:
  std::string inFile(const std::string& what) const
  {
    return files_.size() == 1 ? what : "file '" + files_[file_] + "': " + what;
  }

  bool nextOfFiles(Ros2Message& out)
  {
    McapMessage m;
    while (file_ < files_.size())
    {
      if (!reader_) reader_ = std::make_unique<McapReader>(files_[file_]);
      if (!reader_->next(m))
      {
        reader_.reset();
        file_++;
        continue;
      }
      const McapChannel& c = reader_->channels().at(m.channel_id);
      if (!selected_.count(c.topic)) continue;
      if (c.message_encoding != "cdr")
        throw std::runtime_error("topic '" + c.topic + "' is encoded as '" + c.message_encoding + "', not cdr");
      out.topic = c.topic;
      out.time_ns = m.log_time;
      out.data = zstd_ ? unzstd(m.data) : std::move(m.data);
      return true;
    }
    return false;
  }

  std::vector<std::string> files_;
  bool zstd_;
  std::set<std::string> selected_;
  size_t file_ = 0;
  std::unique_ptr<McapReader> reader_;
};

/** A prepared SQLite statement, finalized at the end of its scope. */
using Statement = std::unique_ptr<sqlite3_stmt, int (*)(sqlite3_stmt*)>;

class Db3Storage : public Ros2Storage
{
 public:
  Db3Storage(std::vector<std::string> files, bool message_zstd) : files_(std::move(files)), zstd_(message_zstd)
  {
    std::map<std::string, BagTopic> by_name;
    for (file_ = 0; file_ < files_.size(); file_++)
    {
      open();
      Statement q = prepare("SELECT t.name, t.type, COUNT(m.id) FROM topics t LEFT JOIN messages m ON m.topic_id = t.id "
                            "GROUP BY t.id");
      int rc;
      while ((rc = sqlite3_step(q.get())) == SQLITE_ROW)
      {
        BagTopic& t = by_name[text(q.get(), 0)];
        t.name = text(q.get(), 0);
        t.type = text(q.get(), 1);
        t.messages += static_cast<size_t>(sqlite3_column_int64(q.get(), 2));
      }
      if (rc != SQLITE_DONE) fail("its topics cannot be listed");
    }
    topics_ = sortedTopics(by_name);
    select({});
  }
  ~Db3Storage() override { close(); }

  void select(const std::vector<std::string>& topics) override
  {
    selected_ = topics;
    file_ = 0;
    close();
  }

  bool next(Ros2Message& out) override
  {
    while (file_ < files_.size())
    {
      if (!db_)
      {
        open();
        std::string sql = "SELECT t.name, m.timestamp, m.data FROM messages m JOIN topics t ON m.topic_id = t.id "
                          "WHERE t.name IN (";
        for (size_t i = 0; i < selected_.size(); i++) sql += i ? ", ?" : "?";
        sql += ") ORDER BY m.timestamp, m.id";
        query_ = prepare(sql);
        for (size_t i = 0; i < selected_.size(); i++)
          sqlite3_bind_text(query_.get(), static_cast<int>(i + 1), selected_[i].c_str(), -1, SQLITE_TRANSIENT);
      }
      const int rc = sqlite3_step(query_.get());
      if (rc == SQLITE_DONE)
      {
        close();
        file_++;
        continue;
      }
      if (rc != SQLITE_ROW) fail("a message cannot be read");
      out.topic = text(query_.get(), 0);
      const int64_t t = sqlite3_column_int64(query_.get(), 1);
      if (t < 0) throw std::runtime_error("a message recorded at " + std::to_string(t) + " ns, before 1970");
      out.time_ns = static_cast<uint64_t>(t);
      const auto* blob = static_cast<const uint8_t*>(sqlite3_column_blob(query_.get(), 2));
      const int n = sqlite3_column_bytes(query_.get(), 2);
      if (static_cast<uint64_t>(n) > kMaxRos2MessageBytes)
        throw std::runtime_error("a message of " + std::to_string(n) + " bytes (at most " +
                                 std::to_string(kMaxRos2MessageBytes) + ")");
      out.data.assign(blob, blob + n);
      if (zstd_) out.data = unzstd(out.data);
      return true;
    }
    return false;
  }

 private:
  void open()
  {
    if (sqlite3_open_v2(files_[file_].c_str(), &db_, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK)
      fail("it cannot be opened");
  }
  void close()
  {
    query_.reset();
    if (db_) sqlite3_close(db_);
    db_ = nullptr;
  }
  Statement prepare(const std::string& sql)
  {
    sqlite3_stmt* s = nullptr;
    if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &s, nullptr) != SQLITE_OK)
    {
      sqlite3_finalize(s);
      fail("it is not a rosbag2 database");
    }
    return Statement(s, sqlite3_finalize);
  }
  static std::string text(sqlite3_stmt* s, int column)
  {
    const auto* p = sqlite3_column_text(s, column);
    return p ? reinterpret_cast<const char*>(p) : "";
  }
  [[noreturn]] void fail(const std::string& what)
  {
    const std::string msg = "rosbag2 file '" + files_[file_] + "': " + what + " (SQLite: " +
                            (db_ ? sqlite3_errmsg(db_) : "no connection") + ")";
    close();
    throw std::runtime_error(msg);
  }

  std::vector<std::string> files_;
  bool zstd_;
  std::vector<std::string> selected_;
  size_t file_ = 0;
  sqlite3* db_ = nullptr;
  Statement query_{nullptr, sqlite3_finalize};
};
}  // namespace

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
      storage = std::make_unique<McapStorage>(layout.files, layout.message_zstd);
    else
      storage = std::make_unique<Db3Storage>(layout.files, layout.message_zstd);
    storage->keep(scratch);
    return storage;
  }
  if (!fs::is_regular_file(path)) throw std::runtime_error("cannot open bag '" + path + "': no such file");
  if (endsWith(path, ".db3")) return std::make_unique<Db3Storage>(std::vector<std::string>{path}, false);
  return std::make_unique<McapStorage>(std::vector<std::string>{path}, false);
}

bool isRos2Bag(const std::string& path)
{
  std::error_code ec;
  if (fs::is_directory(path, ec)) return fs::is_regular_file(fs::path(path) / "metadata.yaml", ec);
  return endsWith(path, ".mcap") || endsWith(path, ".db3") || hasMcapMagic(path);
}

}  // namespace swslam::io

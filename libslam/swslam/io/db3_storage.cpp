#include <swslam/io/ros2_storage.h>

#include <sqlite3.h>

#include <map>

namespace swslam::io
{
namespace
{
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
      if (zstd_) out.data = unzstdMessage(out.data);
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
};}  // namespace

std::unique_ptr<Ros2Storage> openDb3Files(std::vector<std::string> files, bool message_zstd)
{
  return std::make_unique<Db3Storage>(std::move(files), message_zstd);
}

}  // namespace swslam::io

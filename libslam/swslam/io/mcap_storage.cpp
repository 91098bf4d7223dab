#include <swslam/io/mcap_reader.h>
#include <swslam/io/ros2_storage.h>

#include <map>
#include <queue>
#include <utility>
#include <set>

namespace swslam::io
{
namespace
{
/** A message read ahead, waiting for its turn in log-time order (`seq`: its place in the file,
 * which orders messages of one time). */
struct Pending
{
  uint64_t time = 0, seq = 0;
  Ros2Message message;
  bool operator>(const Pending& o) const { return time != o.time ? time > o.time : seq > o.seq; }
};

/** Messages in log-time order, as rosbag2 plays an .mcap file, though its chunks (or the
 * messages in one) may be out of order: the listing pass knows every message's time, so a
 * message read is given once no message after it in the file is earlier; the ones read ahead
 * until then are held, at most kMaxMcapReorderBytes. */
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
        listed_.emplace_back();
        while (reader_->next(m))
        {
          const std::string& topic = reader_->channels().at(m.channel_id).topic;
          by_name[topic].messages++;
          listed_.back().push_back({m.log_time, topic});
        }
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
    pending_ = {};
    held_ = 0;
    reader_done_ = false;
    damage_ = nullptr;
    // earliest_[f][i]: the earliest time of a selected message from the i-th of file f on.
    earliest_.assign(listed_.size(), {});
    for (size_t f = 0; f < listed_.size(); f++)
    {
      earliest_[f].assign(listed_[f].size() + 1, UINT64_MAX);
      for (size_t i = listed_[f].size(); i-- > 0;)
        earliest_[f][i] = std::min(earliest_[f][i + 1],
                                   selected_.count(listed_[f][i].topic) ? listed_[f][i].time : UINT64_MAX);
    }
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
    while (file_ < files_.size())
    {
      if (!reader_)
      {
        reader_ = std::make_unique<McapReader>(files_[file_]);
        read_ = 0;
      }
      const std::vector<uint64_t>* earliest = file_ < earliest_.size() ? &earliest_[file_] : nullptr;
      const uint64_t later = earliest && read_ < earliest->size() ? (*earliest)[read_] : UINT64_MAX;
      if (!pending_.empty() && (pending_.top().time <= later || reader_done_))
        return take(out);
      if (reader_done_)
      {
        if (damage_)  // the messages before it are given
          std::rethrow_exception(std::exchange(damage_, nullptr));
        reader_done_ = false;
        reader_.reset();
        file_++;
        continue;
      }
      readAhead();
    }
    return false;
  }

  /** Reads the next message of the file into pending_ (if of a selected topic); at the end,
   * or at damage once the messages read before it are given, sets reader_done_. */
  void readAhead()
  {
    McapMessage m;
    bool more = false;
    try
    {
      more = reader_->next(m);
    }
    catch (const McapError&)
    {
      damage_ = std::current_exception();  // said once the messages read before it are given
      reader_done_ = true;
      return;
    }
    if (!more)
    {
      reader_done_ = true;
      return;
    }
    read_++;
    const McapChannel& c = reader_->channels().at(m.channel_id);
    if (!selected_.count(c.topic)) return;
    if (c.message_encoding != "cdr")
      throw std::runtime_error("topic '" + c.topic + "' is encoded as '" + c.message_encoding + "', not cdr");
    Pending p;
    p.time = m.log_time;
    p.seq = read_;
    p.message.topic = c.topic;
    p.message.time_ns = m.log_time;
    p.message.data = zstd_ ? unzstdMessage(m.data) : std::move(m.data);
    held_ += p.message.data.size();
    if (held_ > kMaxMcapReorderBytes)
      throw std::runtime_error("its messages are out of log-time order by more than the " +
                               std::to_string(kMaxMcapReorderBytes) + " bytes held to reorder them (at message #" +
                               std::to_string(read_) + " of the file)");
    pending_.push(std::move(p));
  }

  bool take(Ros2Message& out)
  {
    out = std::move(const_cast<Pending&>(pending_.top()).message);
    pending_.pop();
    held_ -= out.data.size();
    return true;
  }

  std::vector<std::string> files_;
  bool zstd_;
  std::set<std::string> selected_;
  size_t file_ = 0;
  std::unique_ptr<McapReader> reader_;
  uint64_t read_ = 0;  ///< messages read from the file so far (all topics)
  bool reader_done_ = false;
  std::exception_ptr damage_;  ///< that ended the file, once pending_ is given
  struct Listed
  {
    uint64_t time;
    std::string topic;
  };
  std::vector<std::vector<Listed>> listed_;  ///< each file's messages, by the listing pass
  std::vector<std::vector<uint64_t>> earliest_;
  std::priority_queue<Pending, std::vector<Pending>, std::greater<Pending>> pending_;
  uint64_t held_ = 0;  ///< bytes in pending_
};
}  // namespace

std::unique_ptr<Ros2Storage> openMcapFiles(std::vector<std::string> files, bool message_zstd)
{
  return std::make_unique<McapStorage>(std::move(files), message_zstd);
}

}  // namespace swslam::io

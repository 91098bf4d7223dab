#include <swslam/io/mcap_reader.h>
#include <swslam/io/ros2_storage.h>

#include <map>
#include <set>

namespace swslam::io
{
namespace
{
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
      out.data = zstd_ ? unzstdMessage(m.data) : std::move(m.data);
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
}  // namespace

std::unique_ptr<Ros2Storage> openMcapFiles(std::vector<std::string> files, bool message_zstd)
{
  return std::make_unique<McapStorage>(std::move(files), message_zstd);
}

}  // namespace swslam::io

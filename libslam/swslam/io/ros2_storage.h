#pragma once
// The messages of a ROS 2 bag, whatever holds them: a rosbag2 folder (metadata.yaml naming
// its .db3 or .mcap files, read in its order), a single .mcap file or a single .db3 file.
// .db3 files are read through SQLite (rosbag2's tables `topics` and `messages`, in timestamp
// order), .mcap files through mcap_reader.h (in log-time order, as rosbag2 plays them, though
// a file's chunks or the messages in one may be out of order: mcap_storage.cpp).
// Messages compressed one by one with zstd (metadata.yaml's compression_mode MESSAGE) are
// decompressed, each bounded by kMaxRos2MessageBytes; files compressed whole (FILE) are
// decompressed into a folder under $TMPDIR first (zstd_file.h), removed with the storage.

#include <swslam/io/bag_reader.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace swslam::io
{
/** [bytes] The largest message read, once decompressed (64 MiB: a scan of 2^20 rays with
 * intensities takes 8 MiB); as for ROS 1 bags. */
constexpr uint64_t kMaxRos2MessageBytes = uint64_t(64) << 20;

/** [bytes] The most an .mcap file's messages read ahead to give them in log-time order may hold
 * (256 MiB: a recorder writes a chunk of a few MiB at a time, in order within a few chunks). */
constexpr uint64_t kMaxMcapReorderBytes = uint64_t(256) << 20;

struct Ros2Message
{
  std::string topic;
  uint64_t time_ns = 0;  ///< the bag's time (when it was recorded)
  std::vector<uint8_t> data;  ///< CDR
};

class Ros2Storage
{
 public:
  virtual ~Ros2Storage() = default;
  /** Its topics (name, type e.g. sensor_msgs/msg/LaserScan, messages), by name. */
  const std::vector<BagTopic>& topics() const { return topics_; }
  /** Starts reading the messages of `topics` from the first. */
  virtual void select(const std::vector<std::string>& topics) = 0;
  /** The next message of the selected topics; false at the end. Throws std::runtime_error
   * naming the damage (the messages before it stay valid). */
  virtual bool next(Ros2Message& out) = 0;
  /** Keeps `folder` (the files it reads, decompressed) as long as the storage lives. */
  void keep(std::shared_ptr<void> folder) { kept_ = std::move(folder); }

 protected:
  std::vector<BagTopic> topics_;  ///< a damaged .mcap file's counts stop at the damage
  std::shared_ptr<void> kept_;
};

/** Opens `path`: a rosbag2 folder, a .mcap or a .db3 file. Throws std::runtime_error naming
 * the problem (no metadata.yaml, a storage other than sqlite3 and mcap, a file that is missing,
 * not of its format or whose zstd compression cannot be undone). */
std::unique_ptr<Ros2Storage> openRos2Storage(const std::string& path);

/** The storages openRos2Storage opens: .mcap files (mcap_storage.cpp: listed once to count their
 * topics' messages, a damaged file counted up to the damage) and .db3 files (db3_storage.cpp);
 * `message_zstd`: each message compressed by itself. */
std::unique_ptr<Ros2Storage> openMcapFiles(std::vector<std::string> files, bool message_zstd);
std::unique_ptr<Ros2Storage> openDb3Files(std::vector<std::string> files, bool message_zstd);

/** A message compressed by itself with zstd, decompressed: its size as its frame states it, at
 * most kMaxRos2MessageBytes and 32768 times its own. Throws std::runtime_error naming it. */
std::vector<uint8_t> unzstdMessage(const std::vector<uint8_t>& in);

/** The topics of a map by name, as a list sorted by name. */
std::vector<BagTopic> sortedTopics(std::map<std::string, BagTopic> by_name);

/** Whether `path` is a ROS 2 bag: a folder holding metadata.yaml, a file whose name ends in
 * .mcap or .db3, or one starting with the MCAP magic. */
bool isRos2Bag(const std::string& path);

}  // namespace swslam::io

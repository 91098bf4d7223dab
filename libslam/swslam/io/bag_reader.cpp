#include <swslam/io/bag_reader.h>

#include <swslam/io/ros1_bag_layout.h>
#include <swslam/io/ros_conversion.h>
#include <swslam/sensor/input_bounds.h>

#include <rosbag/bag.h>
#include <rosbag/view.h>

#include <mrpt/ros1bridge/time.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace swslam::io
{
namespace
{
constexpr const char* kLaserScanType = BagReader::kScanType;
constexpr const char* kOdometryType = "nav_msgs/Odometry";
constexpr const char* kTfStaticTopic = "/tf_static";
/** Larger than any scan (2^20 rays with intensities: 8 MiB); a message size past it is damage. */
constexpr uint32_t kMaxMessageBytes = 64u << 20;
/** Messages of one time read ahead (to give the odometry first), at most. */
constexpr size_t kMaxSameTime = 64;

using LayoutCheck = std::string (*)(const std::vector<uint8_t>&);

/** The message `m` as an M: its definition checked (md5), its bytes copied and their lengths
 * checked by `layout` before ROS deserializes them. Throws std::runtime_error or ros::Exception. */
template <class M>
M decode(const rosbag::MessageInstance& m, LayoutCheck layout)
{
  const std::string want = ros::message_traits::MD5Sum<M>::value();
  if (m.getMD5Sum() != want)
    throw std::runtime_error("its " + m.getDataType() + " definition (md5 " + m.getMD5Sum() +
                             ") is not the one this program reads (md5 " + want + ")");
  const uint32_t size = m.size();
  if (size > kMaxMessageBytes) throw std::runtime_error("it states a size of " + std::to_string(size) + " bytes");
  std::vector<uint8_t> bytes(size);
  ros::serialization::OStream out(bytes.data(), size);
  m.write(out);
  if (layout)
    if (const std::string problem = layout(bytes); !problem.empty()) throw std::runtime_error(problem);
  M msg;
  ros::serialization::IStream in(bytes.data(), size);
  ros::serialization::deserialize(in, msg);
  return msg;
}

bool startsWithBagMagic(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  char magic[8] = {};
  f.read(magic, 7);
  return f.gcount() == 7 && std::string(magic) == "#ROSBAG";
}

/** The topics of `type`, by name. */
std::vector<std::string> topicsOfType(const std::vector<BagTopic>& topics, const std::string& type)
{
  std::vector<std::string> out;
  for (const BagTopic& t : topics)
    if (t.type == type) out.push_back(t.name);
  return out;
}

std::string joined(const std::vector<std::string>& names)
{
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}
}  // namespace

struct BagReader::Bag
{
  rosbag::Bag file;
  std::unique_ptr<rosbag::View> view;  ///< the chosen topics, in time order
  rosbag::View::iterator it;
  Ros1BagLayout layout;  ///< checked before librosbag opened the file
  std::ifstream raw;     ///< the file, to check a chunk before librosbag reads it
  std::vector<std::optional<std::string>> chunk_problems;  ///< by chunk, once checked

  /** Why a message at `time` cannot be read safely ("" if it can): a damaged chunk whose time
   * range holds it (a message lies within its chunk's range: readRos1BagLayout checks it). */
  std::string problemAt(const ros::Time& time)
  {
    const uint64_t t = time.toNSec();
    for (size_t i = 0; i < layout.chunks.size(); i++)
    {
      const Ros1Chunk& c = layout.chunks[i];
      if (t < c.start_ns || t > c.end_ns) continue;
      if (!chunk_problems[i]) chunk_problems[i] = ros1ChunkProblem(raw, c);
      if (!chunk_problems[i]->empty())
        return "the bag is damaged: chunk " + std::to_string(i + 1) + " of " + std::to_string(layout.chunks.size()) +
               " (byte " + std::to_string(c.pos) + ", " + c.compression + "): " + *chunk_problems[i];
    }
    return "";
  }
  /** Throws std::runtime_error if the message `m` cannot be read safely (problemAt). */
  void check(const rosbag::MessageInstance& m)
  {
    if (const std::string problem = problemAt(m.getTime()); !problem.empty()) throw std::runtime_error(problem);
  }
};

BagReader::BagReader(const std::string& path, const BagReaderOptions& opts)
    : BagReaderBase(path), bag_(std::make_unique<Bag>())
{
  if (!std::filesystem::is_regular_file(path)) throw std::runtime_error("cannot open bag '" + path + "': no such file");
  if (!startsWithBagMagic(path))
    throw std::runtime_error("'" + path + "' is not a ROS bag: it does not start with \"#ROSBAG\"");
  // librosbag trusts every length in the file: they are checked first.
  bag_->layout = readRos1BagLayout(path);
  bag_->chunk_problems.resize(bag_->layout.chunks.size());
  bag_->raw.open(path, std::ios::binary);
  try
  {
    bag_->file.open(path, rosbag::bagmode::Read);
  }
  catch (const rosbag::BagUnindexedException&)
  {
    throw std::runtime_error("bag '" + path + "' has no index: its recording was cut short (`rosbag reindex` "
                             "rebuilds the index)");
  }
  catch (const ros::Exception& e)
  {
    throw std::runtime_error("cannot read bag '" + path + "': " + e.what() +
                             " (a truncated bag has lost its index, which is written at its end: `rosbag reindex` "
                             "rebuilds it)");
  }
  try
  {
    rosbag::View all(bag_->file);
    for (const rosbag::ConnectionInfo* c : all.getConnections())
    {
      const bool seen = std::any_of(topics_.begin(), topics_.end(), [&](const BagTopic& t) { return t.name == c->topic; });
      if (!seen) topics_.push_back({c->topic, c->datatype, rosbag::View(bag_->file, rosbag::TopicQuery(c->topic)).size()});
    }
    std::sort(topics_.begin(), topics_.end(), [](const BagTopic& a, const BagTopic& b) { return a.name < b.name; });
    chooseTopics(opts, kLaserScanType, kOdometryType);
    findSensorPose();
    std::vector<std::string> chosen;
    for (const std::string& t : {scan_topic_, odom_topic_})
      if (!t.empty()) chosen.push_back(t);
    if (!chosen.empty())
    {
      bag_->view = std::make_unique<rosbag::View>(bag_->file, rosbag::TopicQuery(chosen));
      total_ = bag_->view->size();
      bag_->it = bag_->view->begin();
    }
  }
  catch (const ros::Exception& e)
  {
    throw std::runtime_error("cannot read bag '" + path + "': " + e.what());
  }
}

BagReader::~BagReader() = default;

void BagReader::findSensorPose()
{
  mounting_.source = "identity";
  if (scan_topic_.empty()) return;
  auto first = [&](const std::string& topic) {
    rosbag::View v(bag_->file, rosbag::TopicQuery(topic));
    if (v.begin() == v.end()) throw std::runtime_error("topic '" + topic + "' has no message");
    bag_->check(*v.begin());
    return *v.begin();
  };
  std::string scan_frame, odom_child;
  try
  {
    scan_frame = decode<sensor_msgs::LaserScan>(first(scan_topic_), laserScanLayoutProblem).header.frame_id;
    if (!odom_topic_.empty()) odom_child = decode<nav_msgs::Odometry>(first(odom_topic_), nullptr).child_frame_id;
  }
  catch (const std::exception& e)
  {
    mounting_.source = std::string("identity (the first message cannot be read: ") + e.what() + ")";
    return;
  }
  std::vector<geometry_msgs::TransformStamped> transforms;
  std::string tf_problem;
  const bool has_tf = std::any_of(topics_.begin(), topics_.end(), [](const BagTopic& t) {
    return t.name == kTfStaticTopic && t.type == "tf2_msgs/TFMessage";
  });
  if (has_tf)
  {
    rosbag::View v(bag_->file, rosbag::TopicQuery(kTfStaticTopic));
    try
    {
      for (const rosbag::MessageInstance& m : v)
      {
        bag_->check(m);
        const auto msg = decode<tf2_msgs::TFMessage>(m, tfMessageLayoutProblem);
        transforms.insert(transforms.end(), msg.transforms.begin(), msg.transforms.end());
      }
    }
    catch (const std::exception& e)  // the scans can still be read
    {
      tf_problem = e.what();
    }
  }
  mounting_ = mountingFromTf(scan_frame, odom_child, transforms, tf_problem, path_);
}

void BagReader::readSameTime()
{
  if (!bag_->view || deferred_error_) return;
  std::optional<ros::Time> time;
  std::string at;  // the message being read, for the error: " (topic at time)"
  try
  {
    while (bag_->it != bag_->view->end() && pending_.size() < kMaxSameTime)
    {
      at.clear();
      const rosbag::MessageInstance& m = *bag_->it;
      std::ostringstream here;
      here << " (" << m.getTopic() << " at " << m.getTime() << ")";
      at = here.str();
      if (time && m.getTime() != *time) break;
      time = m.getTime();
      bag_->check(m);
      // A message without a header stamp (some drivers leave it zero) is stamped with its bag time.
      if (m.getTopic() == scan_topic_)
      {
        auto msg = decode<sensor_msgs::LaserScan>(m, laserScanLayoutProblem);
        if (msg.header.stamp.isZero()) msg.header.stamp = m.getTime();
        pending_.push_back(
            std::make_shared<mrpt::obs::CObservation2DRangeScan>(scanFromRos(msg, scan_topic_, mounting_.pose)));
      }
      else
      {
        auto msg = decode<nav_msgs::Odometry>(m, nullptr);
        if (msg.header.stamp.isZero()) msg.header.stamp = m.getTime();
        pending_.push_back(std::make_shared<mrpt::obs::CObservationOdometry>(odometryFromRos(msg, odom_topic_)));
      }
      ++bag_->it;
    }
  }
  catch (const std::exception& e)  // ros::Exception (rosbag's, deserialization) and ours
  {
    failReading(at, e.what());
  }
  odometryFirst();
}

bool BagReaderBase::next(mrpt::obs::CObservation::Ptr& out)
{
  if (pending_.empty()) readSameTime();
  if (pending_.empty())
  {
    if (deferred_error_) throw *deferred_error_;
    return false;
  }
  out = pending_.front();
  pending_.pop_front();
  read_++;
  return true;
}

void BagReaderBase::chooseTopics(const BagReaderOptions& opts, const std::string& scan_type,
                                 const std::string& odom_type)
{
  scan_topic_ = chooseTopic(topics_, opts.scan_topic, scan_type, "--scan-topic", path_);
  if (opts.read_odometry) odom_topic_ = chooseTopic(topics_, opts.odom_topic, odom_type, "--odom-topic", path_);
}

void BagReaderBase::failReading(const std::string& at, const std::string& what)
{
  const size_t index = read_ + pending_.size();
  deferred_error_ = std::make_shared<BagError>("bag '" + path_ + "': message #" + std::to_string(index) + " of " +
                                                   std::to_string(total_) + " cannot be read" + at + ": " + what,
                                               index);
}

void BagReaderBase::odometryFirst()
{
  std::stable_partition(pending_.begin(), pending_.end(), [](const mrpt::obs::CObservation::Ptr& o) {
    return std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o) != nullptr;
  });
}

double BagReaderBase::fractionRead() const
{
  return total_ == 0 ? 1.0 : std::min(1.0, double(read_) / double(total_));
}

std::string chooseTopic(const std::vector<BagTopic>& topics, const std::string& asked, const std::string& type,
                        const std::string& option, const std::string& path)
{
  if (!asked.empty())
  {
    const auto it = std::find_if(topics.begin(), topics.end(), [&](const BagTopic& t) { return t.name == asked; });
    if (it == topics.end())
      throw std::runtime_error("bag '" + path + "' has no topic '" + asked + "'; its topics: " + formatTopics(topics));
    if (it->type != type)
      throw std::runtime_error("bag '" + path + "': topic '" + asked + "' is " + it->type + ", not " + type);
    return asked;
  }
  const auto names = topicsOfType(topics, type);
  if (names.size() > 1)
    throw std::runtime_error("bag '" + path + "' has " + std::to_string(names.size()) + " " + type + " topics (" +
                             joined(names) + "): choose one with " + option);
  return names.empty() ? "" : names.front();
}

std::string formatTopics(const std::vector<BagTopic>& topics)
{
  if (topics.empty()) return "none";
  std::string s;
  for (const BagTopic& t : topics)
    s += (s.empty() ? "" : ", ") + t.name + " (" + t.type + ", " + std::to_string(t.messages) +
         (t.messages == 1 ? " message)" : " messages)");
  return s;
}

bool isBagFile(const std::string& path)
{
  const std::string ext = ".bag";
  if (path.size() >= ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0) return true;
  return startsWithBagMagic(path);
}

}  // namespace swslam::io

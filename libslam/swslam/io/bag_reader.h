#pragma once
// Streaming reader of ROS 1 bags (format 2.0, through librosbag_storage): the
// sensor_msgs/LaserScan messages of one topic become CObservation2DRangeScan (labelled with
// the topic), the nav_msgs/Odometry messages of one topic CObservationOdometry, in the bag's
// time order; librosbag holds one chunk of the file in memory at a time. The scanner's pose on
// the vehicle is the /tf_static transform from the odometry's child frame (base_link without
// odometry) to the scans' frame, else identity. Each chunk is checked before librosbag reads a
// message of it (ros1_bag_layout.h); a damaged one ends the reading as a damaged message does.

#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>

#include <deque>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace swslam::io
{
/** Thrown when a bag's message cannot be read (damaged data). Everything returned before it
 * stays valid. */
class BagError : public std::runtime_error
{
 public:
  BagError(const std::string& msg, size_t message) : std::runtime_error(msg), message_(message) {}
  /** Index of the message (of those read) that could not be read (0-based). */
  size_t message() const { return message_; }

 private:
  size_t message_;
};

struct BagTopic
{
  std::string name;
  std::string type;  ///< e.g. sensor_msgs/LaserScan
  size_t messages = 0;
};

struct BagReaderOptions
{
  std::string scan_topic;     ///< empty: the bag's only LaserScan topic (none: no scans)
  std::string odom_topic;     ///< empty: the bag's only Odometry topic, if any
  bool read_odometry = true;  ///< false: no odometry, whatever the topics
};

/** A scanner's pose on the vehicle, and where it came from (for the run's report). */
struct SensorMounting
{
  mrpt::poses::CPose3D pose;
  std::string source;
};

/** What the ROS 1 and ROS 2 bag readers share: the topics chosen, the scanner's pose, and
 * the messages of one time read ahead (the odometry first, as in a rawlog), then the error
 * that stopped the reading, given once the messages before it are. */
class BagReaderBase
{
 public:
  virtual ~BagReaderBase() = default;

  /** The next scan or odometry reading, in time order (of one time, the odometry first, as in
   * a rawlog); false at the end. Throws BagError on a message that cannot be read, once the
   * messages before it are returned. */
  bool next(mrpt::obs::CObservation::Ptr& out);

  const std::string& path() const { return path_; }
  const std::vector<BagTopic>& topics() const { return topics_; }
  /** The scans' topic; empty if the bag has no LaserScan topic. */
  const std::string& scanTopic() const { return scan_topic_; }
  /** The odometry's topic; empty if none is read. */
  const std::string& odomTopic() const { return odom_topic_; }
  /** The scanner's pose on the vehicle, and where it came from (for the run's report). */
  const mrpt::poses::CPose3D& sensorPose() const { return mounting_.pose; }
  const std::string& sensorPoseSource() const { return mounting_.source; }
  /** Fraction of the chosen topics' messages read, in [0, 1]. */
  double fractionRead() const;
  size_t messagesRead() const { return read_; }

 protected:
  explicit BagReaderBase(const std::string& path) : path_(path) {}
  /** Reads the messages of the next time into pending_ (none at the end); a message that
   * cannot be read ends the reading through failReading. */
  virtual void readSameTime() = 0;
  /** Picks the scan and odometry topics of these types from topics_ (chooseTopic). */
  void chooseTopics(const BagReaderOptions& opts, const std::string& scan_type, const std::string& odom_type);
  /** Ends the reading after pending_: "bag 'P': message #K of N cannot be read<at>: what". */
  void failReading(const std::string& at, const std::string& what);
  /** Puts the odometry of pending_ first (a bag orders the messages of one time arbitrarily). */
  void odometryFirst();

  std::string path_;
  std::vector<BagTopic> topics_;
  std::string scan_topic_, odom_topic_;
  SensorMounting mounting_;
  std::deque<mrpt::obs::CObservation::Ptr> pending_;
  std::shared_ptr<BagError> deferred_error_;
  size_t read_ = 0, total_ = 0;
};

class BagReader : public BagReaderBase
{
 public:
  /** The name of the format, for the run's report. */
  static constexpr const char* kFormat = "ROS bag";
  static constexpr const char* kScanType = "sensor_msgs/LaserScan";

  /** Opens the bag and picks its topics. Throws std::runtime_error naming the problem if the
   * bag cannot be opened (missing, not a bag, truncated: its index is at its end; a record
   * outside the chunks damaged, ros1_bag_layout.h: librosbag reads none unchecked), if a topic
   * asked for is not in it or not of the right type, if a topic is not asked for and the
   * bag has several of that type, or if its /tf_static mounts the scanner beyond the bound of
   * sensor/input_bounds.h. */
  BagReader(const std::string& path, const BagReaderOptions& opts);
  ~BagReader() override;

 private:
  void findSensorPose();
  void readSameTime() override;

  struct Bag;
  std::unique_ptr<Bag> bag_;
};

/** One topic of `type` (of a bag at `path`, whose `topics` are given): `asked` if not empty
 * (a std::runtime_error if the bag lacks it or it is of another type), else the bag's only
 * one ("" if none; a std::runtime_error naming them if several, to be chosen with
 * `option`). */
std::string chooseTopic(const std::vector<BagTopic>& topics, const std::string& asked, const std::string& type,
                        const std::string& option, const std::string& path);

/** The topics as "name (type, N messages)", comma-separated. */
std::string formatTopics(const std::vector<BagTopic>& topics);

/** Whether `path` is a ROS bag: its name ends in .bag or it starts with "#ROSBAG". */
bool isBagFile(const std::string& path);

}  // namespace swslam::io

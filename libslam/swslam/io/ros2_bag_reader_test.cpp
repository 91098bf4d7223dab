// Reading ROS 2 bags: the same messages give the same observations as a ROS 1 bag (MCAP in
// either byte order, a rosbag2 folder of .db3 files, messages compressed one by one); topics
// chosen or named; a damaged message stops the reading after the good ones. The bags are
// laid out by ros2_test_writers.h and SQLite; tests/ros2_bag_test.sh reads bags written by
// the MCAP project's own writer.
#include <swslam/io/bag_reader.h>
#include <swslam/io/ros2_bag_reader.h>
#include <swslam/io/ros2_test_writers.h>
#include <swslam/io/scan_source.h>

#include "test_support.h"

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <rosbag/bag.h>
#include <sqlite3.h>
#include <zstd.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace swslam::io;
using namespace swslam::io::testing;
using swslam::test::errorOf;
namespace fs = std::filesystem;

namespace
{
constexpr int kScans = 12;

sensor_msgs::LaserScan scanMessage(int k)
{
  sensor_msgs::LaserScan m;
  m.header.stamp = ros::Time(1000 + k / 10, (k % 10) * 100000000u);
  m.header.frame_id = "laser";
  const int rays = 91;
  m.angle_min = static_cast<float>(-M_PI / 2);
  m.angle_increment = static_cast<float>(M_PI / (rays - 1));
  m.angle_max = m.angle_min + m.angle_increment * (rays - 1);
  m.range_min = 0.05f;
  m.range_max = 30.0f;
  for (int i = 0; i < rays; i++) m.ranges.push_back(1.0f + 0.1f * k + 0.01f * i);
  m.ranges[5] = std::nanf("");
  m.ranges[6] = INFINITY;
  return m;
}

nav_msgs::Odometry odomMessage(int k)
{
  nav_msgs::Odometry m;
  m.header.stamp = ros::Time(1000 + k / 10, (k % 10) * 100000000u);  // the scan's time: odometry first
  m.header.frame_id = "odom";
  m.child_frame_id = "base_footprint";
  m.pose.pose.position.x = 0.2 * k;
  m.pose.pose.orientation.z = std::sin(0.01 * k);
  m.pose.pose.orientation.w = std::cos(0.01 * k);
  m.twist.twist.linear.x = 2.0;
  return m;
}

tf2_msgs::TFMessage tfStatic()
{
  tf2_msgs::TFMessage m;
  geometry_msgs::TransformStamped t;
  t.header.frame_id = "base_footprint";
  t.child_frame_id = "laser";
  t.transform.translation.x = 0.25;
  t.transform.translation.z = 0.4;
  t.transform.rotation.z = std::sin(0.05);
  t.transform.rotation.w = std::cos(0.05);
  m.transforms.push_back(t);
  return m;
}

/** (topic, bag time, CDR) in time order: /tf_static first, then each time's scan and odometry. */
struct Msg
{
  std::string topic;
  ros::Time time;
  std::vector<uint8_t> cdr;
};
std::vector<Msg> messages(bool big_endian)
{
  std::vector<Msg> out{{"/tf_static", ros::Time(999), tfMessageCdr(tfStatic(), big_endian)}};
  for (int k = 0; k < kScans; k++)
  {
    out.push_back({"/scan", scanMessage(k).header.stamp, laserScanCdr(scanMessage(k), big_endian)});
    out.push_back({"/odom", odomMessage(k).header.stamp, odometryCdr(odomMessage(k), big_endian)});
  }
  return out;
}

std::string type(const std::string& topic)
{
  if (topic == "/scan") return "sensor_msgs/msg/LaserScan";
  if (topic == "/odom") return "nav_msgs/msg/Odometry";
  return "tf2_msgs/msg/TFMessage";
}

std::string temp(const std::string& name) { return (fs::temp_directory_path() / ("swslam_ros2_" + name)).string(); }

std::string writeRos1Bag(const std::string& name)
{
  const std::string path = temp(name + ".bag");
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  bag.write("/tf_static", ros::Time(999), tfStatic());
  for (int k = 0; k < kScans; k++)
  {
    bag.write("/scan", scanMessage(k).header.stamp, scanMessage(k));
    bag.write("/odom", odomMessage(k).header.stamp, odomMessage(k));
  }
  return path;
}

std::string writeMcap(const std::string& name, bool big_endian)
{
  McapOut f;
  f.add(McapOut::header());
  const std::vector<std::string> topics{"/tf_static", "/scan", "/odom"};
  for (uint16_t i = 0; i < topics.size(); i++)
    f.add(McapOut::schema(i + 1, type(topics[i]))).add(McapOut::channel(i + 1, i + 1, topics[i]));
  for (const Msg& m : messages(big_endian))
  {
    const auto id = static_cast<uint16_t>(std::find(topics.begin(), topics.end(), m.topic) - topics.begin() + 1);
    f.add(McapOut::message(id, m.time.toNSec(), m.cdr));
  }
  const std::string path = temp(name + ".mcap");
  f.write(path);
  return path;
}

std::vector<uint8_t> zstdOf(const std::vector<uint8_t>& b)
{
  std::vector<uint8_t> out(ZSTD_compressBound(b.size()));
  out.resize(ZSTD_compress(out.data(), out.size(), b.data(), b.size(), 3));
  return out;
}

/** A rosbag2 folder of one .db3 file (as rosbag2 lays out its tables); `damage(k, cdr)` may
 * change message k's bytes. */
std::string writeDb3Folder(const std::string& name, bool message_zstd,
                           const std::function<void(size_t, std::vector<uint8_t>&)>& damage = {})
{
  const fs::path dir = temp(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open((dir / "bag_0.db3").c_str(), &db), SQLITE_OK);
  sqlite3_exec(db,
               "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
               "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);"
               "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp INTEGER NOT NULL, "
               "data BLOB NOT NULL);"
               "INSERT INTO topics VALUES (1, '/tf_static', 'tf2_msgs/msg/TFMessage', 'cdr', ''),"
               "(2, '/scan', 'sensor_msgs/msg/LaserScan', 'cdr', ''), (3, '/odom', 'nav_msgs/msg/Odometry', 'cdr', '');",
               nullptr, nullptr, nullptr);
  sqlite3_stmt* insert = nullptr;
  sqlite3_prepare_v2(db, "INSERT INTO messages(topic_id, timestamp, data) VALUES (?, ?, ?)", -1, &insert, nullptr);
  const auto all = messages(false);
  for (size_t k = 0; k < all.size(); k++)
  {
    std::vector<uint8_t> data = message_zstd ? zstdOf(all[k].cdr) : all[k].cdr;
    if (damage) damage(k, data);
    sqlite3_bind_int(insert, 1, all[k].topic == "/tf_static" ? 1 : all[k].topic == "/scan" ? 2 : 3);
    sqlite3_bind_int64(insert, 2, static_cast<int64_t>(all[k].time.toNSec()));
    sqlite3_bind_blob(insert, 3, data.data(), static_cast<int>(data.size()), SQLITE_TRANSIENT);
    EXPECT_EQ(sqlite3_step(insert), SQLITE_DONE);
    sqlite3_reset(insert);
  }
  sqlite3_finalize(insert);
  sqlite3_close(db);
  std::ofstream(dir / "metadata.yaml") << "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: sqlite3\n"
                                       << "  relative_file_paths:\n    - bag_0.db3\n  compression_format: "
                                       << (message_zstd ? "zstd" : "\"\"") << "\n  compression_mode: "
                                       << (message_zstd ? "MESSAGE" : "\"\"") << "\n";
  return dir.string();
}

/** The .db3 folder `name` compressed file by file (rosbag2's compression_mode FILE). */
std::string writeFileZstdFolder(const std::string& name)
{
  const fs::path dir = writeDb3Folder(name, false);
  std::ifstream in(dir / "bag_0.db3", std::ios::binary);
  const std::vector<uint8_t> db((std::istreambuf_iterator<char>(in)), {});
  const std::vector<uint8_t> z = zstdOf(db);
  std::ofstream(dir / "bag_0.db3.zstd", std::ios::binary).write(reinterpret_cast<const char*>(z.data()), z.size());
  fs::remove(dir / "bag_0.db3");
  std::ofstream(dir / "metadata.yaml") << "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: sqlite3\n"
                                       << "  relative_file_paths:\n    - bag_0.db3.zstd\n  compression_format: zstd\n"
                                       << "  compression_mode: FILE\n";
  return dir.string();
}

/** Every observation a reader gives, serialized by MRPT (every field), with its type. */
template <class Reader>
std::vector<std::vector<uint8_t>> observations(Reader& r)
{
  std::vector<std::vector<uint8_t>> out;
  mrpt::obs::CObservation::Ptr o;
  while (r.next(o))
  {
    std::vector<uint8_t> bytes;
    mrpt::serialization::ObjectToOctetVector(o.get(), bytes);
    out.push_back(bytes);
  }
  return out;
}

}  // namespace

TEST(Ros2BagReader, TheSameMessagesGiveTheSameObservationsAsAROS1Bag)
{
  BagReader ros1(writeRos1Bag("ros1"), {});
  const auto expected = observations(ros1);
  ASSERT_EQ(expected.size(), 2u * kScans);
  for (const std::string& path : {writeMcap("le", false), writeMcap("be", true), writeDb3Folder("db3", false),
                                  writeDb3Folder("db3zstd", true), writeFileZstdFolder("db3filezstd")})
  {
    Ros2BagReader r(path, {});
    EXPECT_EQ(r.scanTopic(), "/scan");
    EXPECT_EQ(r.odomTopic(), "/odom");
    EXPECT_EQ(r.sensorPoseSource(), "/tf_static 'base_footprint' -> 'laser'") << path;
    EXPECT_EQ(r.sensorPose(), ros1.sensorPose());
    EXPECT_EQ(formatTopics(r.topics()),
              "/odom (nav_msgs/msg/Odometry, 12 messages), /scan (sensor_msgs/msg/LaserScan, 12 messages), "
              "/tf_static (tf2_msgs/msg/TFMessage, 1 message)");
    EXPECT_TRUE(observations(r) == expected) << path;
    EXPECT_EQ(r.fractionRead(), 1.0);
  }
}

TEST(Ros2BagReader, AScanSourceReadsAFolderOrAFileAsAROS2Bag)
{
  const std::string dir = writeDb3Folder("source", false);
  auto source = openScanSource(dir, {}, {});
  EXPECT_EQ(source->describe(), "ROS 2 bag " + dir +
                                    " (scans /scan, sensor pose /tf_static 'base_footprint' -> 'laser', odometry /odom)");
  swslam::sensor::ScanInput in;
  int n = 0;
  while (source->next(in)) n++;
  EXPECT_EQ(n, kScans);
  EXPECT_EQ(source->stats().odometry, size_t(kScans));
  EXPECT_TRUE(isRos2Bag(writeMcap("named", false)));
  EXPECT_FALSE(isRos2Bag(writeRos1Bag("not_ros2")));
  Ros2BagReader file(dir + "/bag_0.db3", {});  // a .db3 file alone, without its metadata.yaml
  EXPECT_EQ(observations(file).size(), 2u * kScans);
  EXPECT_FALSE(isRos2Bag(fs::temp_directory_path().string()));  // a folder without metadata.yaml
}

TEST(Ros2BagReader, TopicsAreChosenOrNamedAsForROS1)
{
  const std::string mcap = writeMcap("topics", false);
  EXPECT_EQ(errorOf([&] { Ros2BagReader(mcap, {"/front/scan", "", true}); }),
            "bag '" + mcap + "' has no topic '/front/scan'; its topics: /odom (nav_msgs/msg/Odometry, 12 messages), "
            "/scan (sensor_msgs/msg/LaserScan, 12 messages), /tf_static (tf2_msgs/msg/TFMessage, 1 message)");
  EXPECT_EQ(errorOf([&] { Ros2BagReader(mcap, {"", "/scan", true}); }),
            "bag '" + mcap + "': topic '/scan' is sensor_msgs/msg/LaserScan, not nav_msgs/msg/Odometry");
  Ros2BagReader laser_only(mcap, {"", "", false});
  EXPECT_EQ(observations(laser_only).size(), size_t(kScans));
}

TEST(Ros2BagReader, ADamagedMessageStopsTheReadingAfterTheGoodOnes)
{
  // Message 9 of the file (/tf_static, then scan/odometry pairs: scan 4) claims 2^30 rays.
  const std::string dir = writeDb3Folder("damaged", false, [](size_t k, std::vector<uint8_t>& cdr) {
    if (k == 9) cdr.resize(cdr.size() - 8 * 4);  // cut inside its ranges
  });
  Ros2BagReader r(dir, {});
  mrpt::obs::CObservation::Ptr o;
  size_t good = 0;
  const std::string e = errorOf([&] {
    while (r.next(o)) good++;
  });
  EXPECT_EQ(good, 8u);
  EXPECT_EQ(e.rfind("bag '" + dir + "': message #8 of 24 cannot be read (/scan at 1000400000000 ns): CDR byte ", 0), 0u)
      << e;
}

TEST(Ros2BagReader, ATransformOrOdometryWhoseQuaternionIsNoRotationIsNamed)
{
  // Found by the ros2_bag fuzz harness: MRPT threw a logic_error (with its call stack) from the
  // constructor, past the documented errors. The ROS 1 reader shares the check.
  McapOut f;
  f.add(McapOut::header());
  f.add(McapOut::schema(1, "tf2_msgs/msg/TFMessage")).add(McapOut::channel(1, 1, "/tf_static"));
  f.add(McapOut::schema(2, "sensor_msgs/msg/LaserScan")).add(McapOut::channel(2, 2, "/scan"));
  f.add(McapOut::schema(3, "nav_msgs/msg/Odometry")).add(McapOut::channel(3, 3, "/odom"));
  tf2_msgs::TFMessage tf = tfStatic();
  tf.transforms[0].transform.rotation.x = 1e300;
  f.add(McapOut::message(1, 1, tfMessageCdr(tf)));
  f.add(McapOut::message(2, 2, laserScanCdr(scanMessage(0))));
  nav_msgs::Odometry odo = odomMessage(0);
  f.add(McapOut::message(3, 2, odometryCdr(odo)));
  odo.pose.pose.orientation.w = 2;
  f.add(McapOut::message(3, 3, odometryCdr(odo)));
  const std::string path = temp("quaternion.mcap");
  f.write(path);
  EXPECT_EQ(errorOf([&] { Ros2BagReader(path, {}); }),
            "bag '" + path + "': /tf_static 'base_footprint' -> 'laser': a rotation quaternion (1e+300, 0, "
            "0.0499792, 0.99875) of norm inf, not 1");

  McapOut g;  // the same without /tf_static: the second odometry is named when read
  g.add(McapOut::header());
  g.add(McapOut::schema(2, "sensor_msgs/msg/LaserScan")).add(McapOut::channel(2, 2, "/scan"));
  g.add(McapOut::schema(3, "nav_msgs/msg/Odometry")).add(McapOut::channel(3, 3, "/odom"));
  g.add(McapOut::message(2, 2, laserScanCdr(scanMessage(0))));
  g.add(McapOut::message(3, 2, odometryCdr(odomMessage(0))));
  g.add(McapOut::message(3, 3, odometryCdr(odo)));
  g.write(temp("odometry.mcap"));
  Ros2BagReader r(temp("odometry.mcap"), {});
  mrpt::obs::CObservation::Ptr o;
  EXPECT_NE(errorOf([&] {
              while (r.next(o)) {}
            }).find("message #2 of 3 cannot be read (/odom at 3 ns): a rotation quaternion (0, 0, 0, 2) of norm 2, not 1"),
            std::string::npos);
}

TEST(Ros2BagReader, AMessageCompressedByItselfStatingMoreThan64MiBIsNamed)
{
  const std::vector<uint8_t> bomb = zstdOf(std::vector<uint8_t>((64u << 20) + 1, 0));  // a few KiB
  const std::string dir = writeDb3Folder("bomb", true, [&](size_t k, std::vector<uint8_t>& data) {
    if (k == 9) data = bomb;
  });
  Ros2BagReader r(dir, {});
  mrpt::obs::CObservation::Ptr o;
  const std::string e = errorOf([&] {
    while (r.next(o)) {}
  });
  EXPECT_NE(e.find("message #8 of 24 cannot be read: a zstd-compressed message of " +
                   std::to_string(bomb.size()) + " bytes states 67108865 bytes (at most 67108864)"),
            std::string::npos)
      << e;
}

TEST(Ros2BagReader, BadFoldersAndFilesAreNamed)
{
  const fs::path dir = temp("badmeta");
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "metadata.yaml") << "rosbag2_bagfile_information:\n  storage_identifier: cassandra\n";
  EXPECT_EQ(errorOf([&] { Ros2BagReader(dir.string(), {}); }),
            "rosbag2 '" + dir.string() + "': metadata.yaml: storage_identifier 'cassandra' (this program reads "
            "sqlite3 and mcap)");
  std::ofstream(dir / "metadata.yaml") << "rosbag2_bagfile_information:\n  storage_identifier: sqlite3\n"
                                          "  relative_file_paths: [gone.db3]\n";
  EXPECT_EQ(errorOf([&] { Ros2BagReader(dir.string(), {}); }),
            "rosbag2 '" + dir.string() + "': metadata.yaml: its file 'gone.db3' is missing");
  std::ofstream(dir / "metadata.yaml") << "rosbag2_bagfile_information: [\n";
  EXPECT_NE(errorOf([&] { Ros2BagReader(dir.string(), {}); }).find("metadata.yaml cannot be read: "), std::string::npos);
  std::ofstream(dir / "bag.db3") << "not a database at all, just text that is long enough to be a header......";
  EXPECT_NE(errorOf([&] { Ros2BagReader((dir / "bag.db3").string(), {}); }).find("it is not a rosbag2 database"),
            std::string::npos);
}

namespace
{
/** The messages as an .mcap file whose chunks (uncompressed) hold them out of order: the
 * second half of the drive first, each chunk's messages reversed; cut `cut` bytes short. */
std::string writeShuffledMcap(const std::string& name, size_t cut = 0)
{
  const std::vector<Msg> all = messages(false);
  const std::vector<std::string> topics{"/tf_static", "/scan", "/odom"};
  McapOut f;
  f.add(McapOut::header());
  for (uint16_t i = 0; i < topics.size(); i++)
    f.add(McapOut::schema(i + 1, type(topics[i]))).add(McapOut::channel(i + 1, i + 1, topics[i]));
  const auto chunk = [&](size_t from, size_t to) {
    std::vector<uint8_t> records;
    for (size_t i = to; i-- > from;)
    {
      const auto id = static_cast<uint16_t>(std::find(topics.begin(), topics.end(), all[i].topic) - topics.begin() + 1);
      const auto r = McapOut::message(id, all[i].time.toNSec(), all[i].cdr);
      records.insert(records.end(), r.begin(), r.end());
    }
    return McapOut::chunk("", records, records.size(), 0);
  };
  f.add(chunk(all.size() / 2, all.size())).add(chunk(0, all.size() / 2));
  if (cut) f.bytes.resize(f.bytes.size() - cut);
  const std::string path = temp(name + ".mcap");
  f.write(path, cut == 0);
  return path;
}

std::vector<double> times(Ros2BagReader& r)
{
  std::vector<double> out;
  mrpt::obs::CObservation::Ptr o;
  while (r.next(o)) out.push_back(mrpt::Clock::toDouble(o->timestamp));
  return out;
}
}  // namespace

TEST(Ros2BagReader, McapMessagesComeInLogTimeOrderThoughTheFileHoldsThemOtherwise)
{
  // As rosbag2 plays an .mcap file (by its index); they came in file order, steps back.
  Ros2BagReader shuffled(writeShuffledMcap("shuffled"), {}), ordered(writeMcap("ordered", false), {});
  EXPECT_EQ(shuffled.sensorPoseSource(), ordered.sensorPoseSource());
  EXPECT_TRUE(observations(shuffled) == observations(ordered));  // every field of each, in order
  Ros2BagReader again(writeShuffledMcap("shuffled"), {});
  const std::vector<double> t = times(again);
  EXPECT_EQ(t.size(), size_t(2 * kScans));
  EXPECT_TRUE(std::is_sorted(t.begin(), t.end()));
}

TEST(Ros2BagReader, AnMcapCutShortGivesTheMessagesBeforeTheCutInLogTimeOrderThenTheDamage)
{
  // The second chunk (the first half of the drive) cut: the first one's messages, in order.
  const std::string path = writeShuffledMcap("shuffled_cut", 100);
  Ros2BagReader r(path, {});
  std::vector<double> t;
  mrpt::obs::CObservation::Ptr o;
  const std::string e = errorOf([&] {
    while (r.next(o)) t.push_back(mrpt::Clock::toDouble(o->timestamp));
  });
  const size_t all = messages(false).size();
  EXPECT_EQ(t.size(), all - all / 2);  // the first chunk's: the second half of the drive
  EXPECT_TRUE(std::is_sorted(t.begin(), t.end()));
  EXPECT_NE(e.find("cannot be read"), std::string::npos) << e;
  EXPECT_NE(e.find("(a truncated file?)"), std::string::npos) << e;
}

// swslam-localize end to end: lake-short's first 400 scans mapped and saved as a session,
// then a part of them localized on it with no initial pose (the poses agree with the mapping
// run's), on the run folder as on the session; a log of another place is lost at every scan;
// a map that is no map is a named error that writes nothing.
#include <swslam/app/exit_codes.h>
#include <swslam/app/localize_run.h>
#include <swslam/app/offline_run.h>
#include <swslam/common/tum_io.h>
#include <swslam/eval/association.h>
#include <swslam/eval/se2_alignment.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "log_cut_support.h"
#include "test_support.h"

using namespace swslam;
using namespace swslam::app;
namespace fs = std::filesystem;

namespace
{
struct Mapped
{
  std::string dir, run, session, part;
};

/** The first 400 scans mapped (laser only) into DIR/run and saved as DIR/session; scans
 * 150..399 cut as DIR/part.rawlog. Once per test binary. */
const Mapped& mapped()
{
  static const Mapped m = [] {
    Mapped m;
    m.dir = test::tempDir("localize_run");
    const std::string first = test::cutLakeShort(m.dir + "/first.rawlog", 0, 400);
    m.part = test::cutLakeShort(m.dir + "/part.rawlog", 150, 250);
    OfflineRunOptions o;
    o.config = std::string(SWSLAM_SOURCE_DIR) + "/config/default.ini";
    o.input = first;
    o.output = m.run = m.dir + "/run";
    o.save_session = m.session = m.dir + "/session";
    o.deterministic = true;
    o.use_odometry = false;
    o.render = false;
    o.progress = false;
    std::ostringstream out, err;
    EXPECT_EQ(runOffline(o, out, err), kExitOk) << err.str();
    return m;
  }();
  return m;
}

LocalizeOptions options(const std::string& map, const std::string& input, const std::string& output)
{
  LocalizeOptions o;
  o.map = map;
  o.input = input;
  o.output = output;
  o.use_odometry = false;
  return o;
}

std::vector<std::string> csvStates(const std::string& path)
{
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  std::vector<std::string> states;
  while (std::getline(f, line)) states.push_back(line.substr(line.find(',') + 1, line.find(',', line.find(',') + 1) - line.find(',') - 1));
  return states;
}

struct Errors
{
  double rms = 0, max = 0;   ///< against lake-short's reference, in the map frame
  double at_nodes = 0;       ///< largest distance from the map's own node poses at their stamps
  size_t nodes = 0;          ///< localized scans that are map nodes
};

/** The localized poses against lake-short's reference poses (the map frame aligned to the
 * reference on the map's nodes), and against the map's nodes at their own stamps. */
Errors errorsOf(const std::string& localization_tum)
{
  const auto truth = eval::sortedByTime(common::readTum(std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.gt.tum"));
  const auto nodes = eval::sortedByTime(common::readTum(mapped().run + "/keyframes.tum"));
  std::vector<Eigen::Vector2d> a, b;
  for (const auto& n : nodes)
    if (const auto k = eval::closestInTime(truth, n.t, 1e-4))
    {
      a.emplace_back(n.pose.x(), n.pose.y());
      b.emplace_back(truth[*k].pose.x(), truth[*k].pose.y());
    }
  const mrpt::poses::CPose2D map_to_truth = eval::alignSE2(a, b);
  Errors e;
  double sq = 0;
  const auto poses = common::readTum(localization_tum);
  for (const auto& p : poses)
  {
    const auto k = eval::closestInTime(truth, p.t, 1e-4);
    EXPECT_TRUE(k) << p.t;
    if (!k) continue;
    const double d = ((map_to_truth + p.pose) - truth[*k].pose).norm();
    sq += d * d;
    e.max = std::max(e.max, d);
    if (const auto n = eval::closestInTime(nodes, p.t, 1e-4))
    {
      e.nodes++;
      e.at_nodes = std::max(e.at_nodes, (p.pose - nodes[*n].pose).norm());
    }
  }
  e.rms = poses.empty() ? 0 : std::sqrt(sq / double(poses.size()));
  return e;
}

/** The mapping run itself scores so on the same scans (its every-scan trajectory). */
void expectAsGoodAsTheMap(const Errors& e)
{
  EXPECT_LT(e.rms, 0.03);
  EXPECT_LT(e.max, 0.08);
  EXPECT_GT(e.nodes, 10u);
  EXPECT_LT(e.at_nodes, 1e-3);  // a map node's own scan is matched onto itself
}
}  // namespace

TEST(LocalizeRun, ALogIsLocalizedOnASessionWithNoInitialPose)
{
  const std::string out_dir = test::tempDir("localize_on_session");
  std::ostringstream out, err;
  ASSERT_EQ(runLocalize(options(mapped().session, mapped().part, out_dir), out, err), kExitOk) << err.str();
  EXPECT_NE(out.str().find("first localized: scan 0,"), std::string::npos) << out.str();
  // The map's own log again: nothing changed.
  EXPECT_NE(out.str().find("changes since the map: 0 appeared, 0 disappeared"), std::string::npos) << out.str();
  EXPECT_TRUE(fs::is_regular_file(out_dir + "/changes.md"));
  EXPECT_TRUE(fs::is_regular_file(out_dir + "/changes.png"));
  const auto states = csvStates(out_dir + "/localization.csv");
  ASSERT_EQ(states.size(), 250u);
  EXPECT_EQ(states.front(), "relocalized");
  EXPECT_EQ(std::count(states.begin(), states.end(), "lost"), 0);
  EXPECT_EQ(common::readTum(out_dir + "/localization.tum").size(), 250u);
  expectAsGoodAsTheMap(errorsOf(out_dir + "/localization.tum"));
  EXPECT_TRUE(fs::is_regular_file(out_dir + "/summary.md"));
}

TEST(LocalizeRun, ARunFolderIsAMapTooAndAnInitialPoseIsTrackedFrom)
{
  const std::string out_dir = test::tempDir("localize_on_run");
  LocalizeOptions o = options(mapped().run, mapped().part, out_dir);
  const auto start = common::readTum(mapped().run + "/trajectory.tum")[150].pose;
  o.initial_pose = std::array<double, 3>{start.x() + 0.1, start.y() - 0.1, mrpt::RAD2DEG(start.phi()) + 2};
  std::ostringstream out, err;
  ASSERT_EQ(runLocalize(o, out, err), kExitOk) << err.str();
  const auto states = csvStates(out_dir + "/localization.csv");
  ASSERT_EQ(states.size(), 250u);
  EXPECT_EQ(states.front(), "tracked");
  EXPECT_EQ(std::count(states.begin(), states.end(), "relocalized"), 0);
  expectAsGoodAsTheMap(errorsOf(out_dir + "/localization.tum"));
}

TEST(LocalizeRun, ALogOfAnotherPlaceIsLostAtEveryScan)
{
  const std::string out_dir = test::tempDir("localize_elsewhere");
  std::ostringstream out, err;
  const std::string room = std::string(SWSLAM_SOURCE_DIR) + "/tests/data/raw-room.clf.gz";
  EXPECT_EQ(runLocalize(options(mapped().session, room, out_dir), out, err), kExitInputError);
  EXPECT_NE(err.str().find("no scan was localized"), std::string::npos) << err.str();
  const auto states = csvStates(out_dir + "/localization.csv");
  ASSERT_FALSE(states.empty());
  EXPECT_EQ(static_cast<size_t>(std::count(states.begin(), states.end(), "lost")), states.size());
  EXPECT_TRUE(common::readTum(out_dir + "/localization.tum").empty());
}

TEST(LocalizeRun, AFolderThatIsNoMapIsANamedErrorAndNothingIsWritten)
{
  const std::string dir = test::tempDir("localize_no_map");
  std::ostringstream out, err;
  EXPECT_EQ(runLocalize(options(dir + "/missing", mapped().part, dir + "/out"), out, err), kExitUsage);
  EXPECT_NE(err.str().find("no such folder"), std::string::npos) << err.str();
  fs::create_directories(dir + "/empty");
  std::ostringstream out2, err2;
  EXPECT_EQ(runLocalize(options(dir + "/empty", mapped().part, dir + "/out"), out2, err2), kExitUsage);
  EXPECT_NE(err2.str().find("run.ini is missing"), std::string::npos) << err2.str();
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

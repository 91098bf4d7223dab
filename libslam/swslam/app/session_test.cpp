// Sessions: lake-short cut in two, the first part saved as a session and the second resumed
// from it. The resumed run holds the session's nodes and its own, joined by their edges,
// twice the same; a damaged session, or -c beside --resume, is a named error that writes
// nothing; a session is replaced only by a whole one.
#include <swslam/app/exit_codes.h>
#include <swslam/app/offline_run.h>
#include <swslam/app/session.h>
#include <swslam/common/tum_io.h>
#include <swslam/graph/io.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include "log_cut_support.h"
#include "test_support.h"

using namespace swslam;
using namespace swslam::app;
namespace fs = std::filesystem;

namespace
{
constexpr size_t kFirstScans = 400, kSecondScans = 400;

struct Split
{
  std::string dir, first, second;
};

const Split& split()
{
  static const Split s = [] {
    Split s;
    s.dir = test::tempDir("session_split");
    s.first = test::cutLakeShort(s.dir + "/first.rawlog", 0, kFirstScans);
    s.second = test::cutLakeShort(s.dir + "/second.rawlog", kFirstScans, kSecondScans);
    return s;
  }();
  return s;
}

OfflineRunOptions laserOnly(const std::string& input, const std::string& output)
{
  OfflineRunOptions o;
  o.input = input;
  o.output = output;
  o.deterministic = true;
  o.use_odometry = false;
  o.render = false;
  o.progress = false;
  return o;
}

/** The first part, saved as a session in DIR/session (once per test binary). */
std::string savedSession()
{
  static const std::string session = [] {
    const std::string dir = test::tempDir("session_saved");
    OfflineRunOptions o = laserOnly(split().first, dir + "/out");
    o.config = std::string(SWSLAM_SOURCE_DIR) + "/config/default.ini";
    o.save_session = dir + "/session";
    std::ostringstream out, err;
    EXPECT_EQ(runOffline(o, out, err), kExitOk) << err.str();
    return o.save_session;
  }();
  return session;
}

std::string readText(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}
}  // namespace

TEST(Session, AResumedRunContinuesTheSessionsGraphTheSameEachTime)
{
  const Session saved = readSession(savedSession());
  const size_t n0 = saved.resumed.graph.nodeCount();
  ASSERT_GT(n0, 20u);
  EXPECT_EQ(saved.resumed.observations.size(), n0);
  EXPECT_EQ(saved.record.input, fs::absolute(split().first).lexically_normal().string());

  const std::string dir = test::tempDir("session_resumed");
  std::string trajectories[2];
  for (int k = 0; k < 2; k++)
  {
    OfflineRunOptions o = laserOnly(split().second, dir + "/out" + std::to_string(k));
    o.resume = savedSession();
    std::ostringstream out, err;
    ASSERT_EQ(runOffline(o, out, err), kExitOk) << err.str();
    EXPECT_NE(err.str().find("resuming the session in " + savedSession() + " (" + std::to_string(n0) + " nodes)"),
              std::string::npos)
        << err.str();
    trajectories[k] = readText(o.output + "/trajectory.tum");
  }
  EXPECT_EQ(trajectories[0], trajectories[1]);
  // A resumed run reports what changed since the session (lake-short's bank did not move);
  // a run that resumed nothing does not.
  EXPECT_NE(readText(dir + "/out0/changes.md").find("Compared "), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(dir + "/out0/changes.png"));
  EXPECT_FALSE(fs::exists(fs::path(savedSession()).parent_path() / "out" / "changes.md"));
  EXPECT_EQ(readText(dir + "/out0/graph.graph"), readText(dir + "/out1/graph.graph"));

  // The session's nodes first, as saved, then the new ones; the trajectory is this run's scans.
  const auto keyframes = common::readTum(dir + "/out0/keyframes.tum");
  ASSERT_GT(keyframes.size(), n0 + 20);
  for (size_t id = 0; id < n0; id++) EXPECT_EQ(keyframes[id].t, saved.node_times[id]) << id;
  EXPECT_GT(keyframes[n0].t, keyframes[n0 - 1].t);
  EXPECT_EQ(common::readTum(dir + "/out0/trajectory.tum").size(), kSecondScans);
  // Joined: the first new node's consecutive edge comes from the session's last, and the new
  // nodes near the session's end are matched against its nodes.
  const graph::PoseGraph g = graph::loadGraph(dir + "/out0/graph.graph");
  size_t joining = 0;
  bool consecutive = false;
  for (size_t k = 0; k < g.edgeCount(); k++)
  {
    const auto& e = g.edge(k);
    if (std::min(e.from, e.to) < n0 && std::max(e.from, e.to) >= n0) joining++;
    consecutive |= e.from == n0 - 1 && e.to == n0 && e.kind == graph::EdgeKind::Consecutive;
  }
  EXPECT_TRUE(consecutive);
  EXPECT_GT(joining, 5u);
  // No jump where the sessions meet: the first new node is where tracking left the last.
  EXPECT_LT((g.pose(n0) - g.pose(n0 - 1)).norm(), 1.0);
}

TEST(Session, ADamagedSessionOrAConfigBesideItIsANamedErrorAndNothingIsWritten)
{
  const std::string dir = test::tempDir("session_damaged");
  auto damaged = [&](const std::string& name, const std::function<void(const std::string&)>& damage) {
    const std::string copy = dir + "/" + name;
    fs::copy(savedSession(), copy, fs::copy_options::recursive);
    damage(copy);
    return copy;
  };
  auto expectRefused = [&](const std::string& session, const std::string& words, const std::string& config = "") {
    OfflineRunOptions o = laserOnly(split().second, dir + "/out-" + fs::path(session).filename().string());
    o.resume = session;
    o.config = config;
    std::ostringstream out, err;
    EXPECT_EQ(runOffline(o, out, err), kExitUsage) << session << ": " << err.str();
    EXPECT_NE(err.str().find(words), std::string::npos) << session << ": " << err.str();
    EXPECT_FALSE(fs::exists(o.output)) << session;
  };
  auto replaceIn = [](const std::string& path, const std::string& from, const std::string& to) {
    std::string t = readText(path);
    const size_t at = t.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    std::ofstream(path, std::ios::binary | std::ios::trunc) << t.replace(at, from.size(), to);
  };
  expectRefused(damaged("format", [&](const std::string& d) { replaceIn(d + "/session.ini", "format = 2", "format = 3"); }),
                "format 3, this swslam reads 1 to 2");
  expectRefused(damaged("no-graph", [](const std::string& d) { fs::remove(d + "/graph.graph"); }),
                "graph.graph is missing");
  expectRefused(damaged("short-rawlog",
                        [](const std::string& d) { fs::resize_file(d + "/nodes.rawlog", fs::file_size(d + "/nodes.rawlog") / 2); }),
                "nodes.rawlog");
  expectRefused(damaged("keyframes", [&](const std::string& d) {
                  const std::string t = readText(d + "/keyframes.tum");
                  std::ofstream(d + "/keyframes.tum", std::ios::trunc) << t.substr(0, t.rfind('\n', t.size() - 2) + 1);
                }),
                "keyframes.tum holds");
  expectRefused(damaged("graph-line", [&](const std::string& d) { replaceIn(d + "/graph.graph", "EDGE_SE2 0 1 ", "EDGE_SE2 0 1 x"); }),
                "graph.graph line");
  expectRefused(damaged("resolution", [&](const std::string& d) { replaceIn(d + "/run.ini", "[map]\n", "[map]\nresolutio = 0.1\n"); }),
                "resolutio");
  expectRefused(savedSession(), "-c is not allowed", std::string(SWSLAM_SOURCE_DIR) + "/config/default.ini");
  expectRefused(dir + "/nowhere", "session.ini is missing");
  // Saving a session over the output folder (or a folder holding it) would take the outputs.
  for (const std::string& over : {dir + "/out-over", dir})
  {
    OfflineRunOptions o = laserOnly(split().second, dir + "/out-over");
    o.save_session = over;
    std::ostringstream out, err;
    EXPECT_EQ(runOffline(o, out, err), kExitUsage) << err.str();
    EXPECT_NE(err.str().find("holds the output folder"), std::string::npos) << err.str();
    EXPECT_FALSE(fs::exists(dir + "/out-over"));
  }
}

TEST(Session, ASessionIsReplacedOnlyByAWholeOne)
{
  const std::string dir = test::tempDir("session_replaced");
  const std::string target = dir + "/session";
  fs::copy(savedSession(), target, fs::copy_options::recursive);
  const std::string before = readText(target + "/graph.graph");
  const Session s = readSession(target);
  system::RunResults results;
  results.graph = s.resumed.graph;
  for (size_t id = 0; id < s.node_times.size(); id++) results.keyframes.push_back({s.node_times[id], s.resumed.graph.pose(id)});
  RunRecord record = s.record;
  // One observation short: refused before anything is touched.
  auto fewer = s.resumed.observations;
  fewer.pop_back();
  EXPECT_THROW(writeSession(target, record, results, mrpt::maps::COccupancyGridMap2D(), fewer), std::invalid_argument);
  EXPECT_EQ(readText(target + "/graph.graph"), before);
  // A whole one replaces it, and leaves nothing beside it.
  results.graph.setPose(0, mrpt::poses::CPose2D(0.5, 0, 0));
  writeSession(target, record, results, mrpt::maps::COccupancyGridMap2D(), s.resumed.observations);
  EXPECT_NE(readText(target + "/graph.graph"), before);
  EXPECT_EQ(readSession(target).resumed.graph.pose(0).x(), 0.5);
  size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.path().filename() != "session";
  EXPECT_EQ(entries, 0u);
}

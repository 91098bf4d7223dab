// Every map output loads back, and a failed write leaves the previous file intact.
#include "map_test_support.h"
#include "test_support.h"

#include <swslam/map/builder.h>
#include <swslam/map/files.h>
#include <swslam/map/map_picture.h>
#include <swslam/map/octomap_export.h>
#include <swslam/map/outputs.h>
#include <swslam/map/render.h>

#include <mrpt/containers/yaml.h>
#include <mrpt/img/CImage.h>

#include <octomap/OcTree.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace swslam;
using namespace swslam::map;
using mrpt::poses::CPose2D;
namespace fs = std::filesystem;

namespace
{
/** A small room map from three nodes, with a grid origin that is not at the world origin. */
mrpt::maps::COccupancyGridMap2D roomMap()
{
  MapParams p;
  p.resolution = 0.1;
  p.initial_half_size = 3;
  p.grow_margin = 1;
  MapBuilder m(p);
  const std::vector<CPose2D> poses = {{-5, 0, 0}, {0, 1, 1.2}, {5, -2, 2.8}};
  for (size_t k = 0; k < poses.size(); k++)
  {
    std::mt19937 rng(k);
    for (int rep = 0; rep < 3; rep++)
      m.insert(10 * k + rep, test::simulateObservation(test::roomWorld(), poses[k], 541, 1.5 * M_PI, 30, 0.01, rng), poses[k]);
  }
  return m.snapshot();
}

std::string readAll(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/** Makes the next atomic write of `path` fail: a directory squats its temporary name. */
std::string blockAtomicWrite(const std::string& path)
{
  const fs::path p(path);
  const fs::path squat = p.parent_path() / ("." + p.stem().string() + ".tmp" +
                                            std::to_string(::getpid()) + p.extension().string());
  fs::create_directories(squat / "x");
  return squat.string();
}
}  // namespace

TEST(MapFiles, GridmapLoadsBackIdentical)
{
  const auto g = roomMap();
  const auto dir = test::tempDir("map_gridmap");
  writeGridmap(g, dir + "/map.gridmap.gz");
  const auto back = readGridmap(dir + "/map.gridmap.gz");
  EXPECT_EQ(back.getSizeX(), g.getSizeX());
  EXPECT_FLOAT_EQ(back.getXMin(), g.getXMin());
  EXPECT_FLOAT_EQ(back.getResolution(), g.getResolution());
  EXPECT_EQ(test::differingCells(back, g), 0u);
  std::ofstream(dir + "/junk.gz") << "not a map";
  EXPECT_THROW(readGridmap(dir + "/junk.gz"), std::runtime_error);
  EXPECT_THROW(readGridmap(dir + "/missing.gz"), std::runtime_error);
}

TEST(MapFiles, RosMapParsesAndLoadsInMrpt)
{
  const auto g = roomMap();
  const auto dir = test::tempDir("map_ros");
  writeRosMap(g, dir + "/map.yaml", {0.65, 0.196});

  const auto y = mrpt::containers::yaml::FromFile(dir + "/map.yaml");
  EXPECT_EQ(y["image"].as<std::string>(), "map.pgm");
  EXPECT_NEAR(y["resolution"].as<double>(), g.getResolution(), 1e-7);
  const auto origin = y["origin"].toStdVector<double>();
  ASSERT_EQ(origin.size(), 3u);
  EXPECT_NEAR(origin[0], g.getXMin(), 1e-6);
  EXPECT_NEAR(origin[1], g.getYMin(), 1e-6);
  EXPECT_EQ(y["negate"].as<int>(), 0);
  EXPECT_DOUBLE_EQ(y["occupied_thresh"].as<double>(), 0.65);
  EXPECT_DOUBLE_EQ(y["free_thresh"].as<double>(), 0.196);

  // The image: binary PGM, first row = largest y, pixel = 255 p(free).
  const std::string pgm = readAll(dir + "/map.pgm");
  std::istringstream in(pgm);
  std::string magic;
  unsigned w = 0, h = 0, maxval = 0;
  in >> magic >> w >> h >> maxval;
  in.get();
  ASSERT_EQ(magic, "P5");
  ASSERT_EQ(w, g.getSizeX());
  ASSERT_EQ(h, g.getSizeY());
  ASSERT_EQ(maxval, 255u);
  const size_t header = static_cast<size_t>(in.tellg());
  ASSERT_EQ(pgm.size(), header + size_t(w) * h);
  auto pixel = [&](unsigned cx, unsigned cy) {
    return static_cast<unsigned char>(pgm[header + size_t(h - 1 - cy) * w + cx]);
  };
  const auto loaded = mrpt::maps::COccupancyGridMap2D::FromROSMapServerYAML(dir + "/map.yaml");
  ASSERT_EQ(loaded.getSizeX(), w);
  ASSERT_EQ(loaded.getSizeY(), h);
  EXPECT_NEAR(loaded.getXMin(), g.getXMin(), 1e-4);
  EXPECT_NEAR(loaded.getYMin(), g.getYMin(), 1e-4);
  size_t occupied = 0, free = 0;
  for (unsigned cy = 0; cy < h; cy++)
    for (unsigned cx = 0; cx < w; cx++)
    {
      ASSERT_NEAR(pixel(cx, cy), 255.0 * g.getCell(cx, cy), 0.51);
      const double p_occ = 1.0 - std::max(0.01, std::min(0.99, pixel(cx, cy) / 255.0));
      const float expected = p_occ > 0.65 ? 0.0f : p_occ < 0.196 ? 1.0f : 0.5f;
      ASSERT_NEAR(loaded.getCell(cx, cy), expected, 0.02) << cx << " " << cy;
      occupied += expected == 0.0f, free += expected == 1.0f;
    }
  EXPECT_GT(occupied, 100u);
  EXPECT_GT(free, 1000u);
  EXPECT_THROW(writeRosMap(g, dir + "/map.txt", {}), std::invalid_argument);
}

TEST(MapFiles, OctomapHoldsAVoxelPerOccupiedAndPerFreeCell)
{
  const auto g = roomMap();
  const auto dir = test::tempDir("map_bt");
  const OctomapCounts n = writeOctomap(g, dir + "/map.bt", 0.65, 0.25);
  EXPECT_EQ(n.occupied, countOccupied(g, 0.65));
  ASSERT_GT(n.occupied, 100u);
  ASSERT_GT(n.free, 1000u);  // the space the rays crossed
  octomap::OcTree tree(0.5);
  ASSERT_TRUE(tree.readBinary(dir + "/map.bt"));
  EXPECT_NEAR(tree.getResolution(), g.getResolution(), 1e-7);
  size_t occupied = 0, free = 0;
  for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it)
  {
    ASSERT_EQ(it.getDepth(), tree.getTreeDepth());
    const auto c = it.getCoordinate();
    EXPECT_NEAR(c.z(), 0.5 * g.getResolution(), 1e-6);
    const double p = 1.0 - g.getPos(c.x(), c.y());
    if (tree.isNodeOccupied(*it))
    {
      EXPECT_GT(p, 0.65) << c.x() << " " << c.y();
      occupied++;
    }
    else
    {
      EXPECT_LT(p, 0.25) << c.x() << " " << c.y();
      free++;
    }
  }
  EXPECT_EQ(occupied, n.occupied);
  EXPECT_EQ(free, n.free);
  // An unobserved cell is unknown: no voxel.
  EXPECT_EQ(tree.search(octomap::point3d(g.getXMin() + 1e-3, g.getYMin() + 1e-3, 0.5 * g.getResolution())), nullptr);
}

TEST(MapFiles, FailedWriteLeavesThePreviousFileIntact)
{
  const auto g = roomMap();
  auto empty = g;
  empty.fill(0.5f);
  const auto dir = test::tempDir("map_atomic");
  using Writer = std::function<void(const mrpt::maps::COccupancyGridMap2D&, const std::string&)>;
  const std::vector<std::pair<std::string, Writer>> writers = {
      {"map.gridmap.gz", [](const auto& m, const auto& p) { writeGridmap(m, p); }},
      {"map.png", [](const auto& m, const auto& p) { writeMapPicture(m, Overlay(), p); }},
      {"map.yaml", [](const auto& m, const auto& p) { writeRosMap(m, p, {}); }},
      {"map.bt", [](const auto& m, const auto& p) { writeOctomap(m, p, 0.65, 0.25); }},
      {"render.png", [](const auto& m, const auto& p) {
         renderMap(m, Overlay(), p, 240, 200);
       }},
  };
  for (const auto& [file, write] : writers)
  {
    const std::string path = dir + "/" + file;
    try
    {
      write(g, path);
    }
    catch (const std::runtime_error& e)
    {
      // Only the render may be unavailable (no EGL driver); it says so.
      ASSERT_EQ(file, "render.png") << e.what();
      ASSERT_NE(std::string(e.what()).find("EGL"), std::string::npos) << e.what();
      continue;
    }
    const std::string before = readAll(path);
    ASSERT_FALSE(before.empty()) << file;
    const auto squat = blockAtomicWrite(path);
    EXPECT_THROW(write(empty, path), std::runtime_error) << file;
    EXPECT_EQ(readAll(path), before) << file;
    fs::remove_all(squat);
  }
  // The ROS pair: a failed image leaves the old yaml and the old image.
  const auto pgm_before = readAll(dir + "/map.pgm");
  const auto squat = blockAtomicWrite(dir + "/map.pgm");
  EXPECT_THROW(writeRosMap(empty, dir + "/map.yaml", {}), std::runtime_error);
  EXPECT_EQ(readAll(dir + "/map.pgm"), pgm_before);
  fs::remove_all(squat);
}

TEST(MapFiles, WriteMapOutputsWritesEveryFile)
{
  const auto g = roomMap();
  const auto dir = test::tempDir("map_outputs");
  Overlay r;
  r.nodes = {{-5, 0, 0}, {0, 1, 1.2}, {5, -2, 2.8}};
  r.edges = {{0, 1}, {1, 2}, {0, 2, EdgeLook::Loop}};
  r.trajectory = r.nodes;
  const auto problems = writeMapOutputs(dir, g, MapParams(), r);
  for (const auto& p : problems)
  {
    // Without an EGL driver only the render may fail, and it says why.
    EXPECT_EQ(p.file, "render.png") << p.message;
    EXPECT_NE(p.message.find("EGL"), std::string::npos) << p.message;
  }
  for (const char* f : {"map.gridmap.gz", "map.png", "map.yaml", "map.pgm", "map.bt"})
    EXPECT_TRUE(fs::is_regular_file(dir + "/" + f)) << f;
  if (problems.empty()) EXPECT_TRUE(fs::is_regular_file(dir + "/render.png"));
  // A missing output folder is created; a path that is a file is an error.
  EXPECT_TRUE(writeMapOutputs(dir + "/new/sub", g, MapParams(), Overlay(), false).empty());
  EXPECT_TRUE(fs::is_regular_file(dir + "/new/sub/map.png"));
  EXPECT_THROW(writeMapOutputs(dir + "/map.png", g, MapParams(), Overlay(), false), std::invalid_argument);
}

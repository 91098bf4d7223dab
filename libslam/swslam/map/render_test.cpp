// render.png: an off-screen (EGL) picture of the map with the trajectory and graph edges.
#include "test_support.h"

#include <swslam/map/builder.h>
#include <swslam/map/render.h>

#include <mrpt/img/CImage.h>

#include <gtest/gtest.h>

using namespace swslam;
using namespace swslam::map;
using mrpt::poses::CPose2D;

namespace
{
size_t countPixels(const mrpt::img::CImage& img, int r, int g, int b)
{
  size_t n = 0;
  for (int y = 0; y < int(img.getHeight()); y++)
    for (int x = 0; x < int(img.getWidth()); x++)
    {
      const uint8_t* px = img(x, y);  // BGR
      n += std::abs(px[2] - r) < 40 && std::abs(px[1] - g) < 40 && std::abs(px[0] - b) < 40;
    }
  return n;
}
}  // namespace

TEST(MapRender, DrawsMapTrajectoryAndEdges)
{
  MapParams p;
  p.resolution = 0.1;
  MapBuilder m(p);
  RenderInput in;
  for (int k = 0; k < 4; k++)
  {
    const CPose2D pose(-6 + 4 * k, 2 * std::sin(k), 0.2 * k);
    std::mt19937 rng(k);
    m.insert(k, test::simulateObservation(test::roomWorld(), pose, 361, 1.5 * M_PI, 30, 0.01, rng), pose);
    in.nodes.push_back(pose);
    in.trajectory.push_back(pose);
    if (k) in.edges.emplace_back(k - 1, k);
  }
  in.edges.emplace_back(0, 3);
  in.width = 400, in.height = 300;
  const auto path = test::tempDir("map_render") + "/render.png";
  try
  {
    renderMap(m.snapshot(), in, path);
  }
  catch (const std::runtime_error& e)
  {
    if (std::string(e.what()).find("EGL") != std::string::npos) GTEST_SKIP() << e.what();
    throw;
  }
  mrpt::img::CImage img;
  ASSERT_TRUE(img.loadFromFile(path, 1));
  EXPECT_EQ(img.getWidth(), 400u);
  EXPECT_EQ(img.getHeight(), 300u);
  EXPECT_GT(countPixels(img, 230, 30, 30), 300u);   // trajectory
  EXPECT_GT(countPixels(img, 40, 90, 230), 100u);   // edge 0-3
  EXPECT_GT(countPixels(img, 255, 255, 255), 10000u);  // free space
  EXPECT_GT(countPixels(img, 0, 0, 0), 200u);       // walls

  in.edges.emplace_back(1, 9);
  EXPECT_THROW(renderMap(m.snapshot(), in, path), std::invalid_argument);
}

// render.png: an off-screen (EGL) picture of the map with the trajectory and the graph's edges
// by kind, framed like map.png; checked on its pixels against walls at known places.
#include "picture_test_support.h"
#include "test_support.h"

#include <swslam/map/render.h>

#include <mrpt/img/CImage.h>

#include <gtest/gtest.h>

using namespace swslam;
using namespace swslam::map;
using mrpt::poses::CPose2D;

TEST(MapRender, DrawsEdgesByKindOverTheTrajectoryWithMarksScaleBarAndLegend)
{
  const auto g = test::wallGrid();
  Overlay o;
  for (int i = 0; i <= 60; i++) o.trajectory.emplace_back(-8 + 0.25 * i, -4 + 4 * std::sin(0.05 * i), 0);
  for (int i = 0; i <= 60; i += 10) o.nodes.push_back(o.trajectory[i]);
  for (size_t i = 1; i < o.nodes.size(); i++) o.edges.push_back({i - 1, i, EdgeLook::Consecutive});
  o.edges.push_back({0, 6, EdgeLook::Loop});
  o.edges.push_back({1, 5, EdgeLook::Loop, /*switched_off=*/true});
  o.edges.push_back({2, 4, EdgeLook::DenseNeighbour});
  RenderLayout layout;
  mrpt::img::CImage img;
  try
  {
    img = renderMapImage(g, o, 900, 700, &layout);
  }
  catch (const std::runtime_error& e)
  {
    if (std::string(e.what()).find("EGL") != std::string::npos) GTEST_SKIP() << e.what();
    throw;
  }
  EXPECT_EQ(img.getWidth(), 900u);
  EXPECT_EQ(img.getHeight(), 700u);
  // Above or below the graph, clear of the legend and the scale bar.
  const double y = test::clearRow(layout.view, layout.legend, layout.scale_bar, {4.5, 1.0, -5.0});
  ASSERT_FALSE(std::isnan(y));
  const auto centre = layout.view.toImage(0, y);
  const test::WallFrame f = test::measureWalls(img, int(centre.x), int(centre.y));
  const double m = f.metresPerPixel();
  EXPECT_NEAR(m, layout.view.metres_per_pixel, 0.02 * m);
  EXPECT_NEAR(f.metresPerPixelY(), m, 0.02 * m);

  // Start and end marks where the trajectory starts and ends.
  const auto& s = o.trajectory.front();
  const auto& e = o.trajectory.back();
  EXPECT_TRUE(test::near(img, int(f.u(s.x())), int(f.v(s.y())), colors::kStart));
  EXPECT_TRUE(test::near(img, int(f.u(e.x())), int(f.v(e.y())), colors::kEnd));
  // Each kind of edge visible in its own colour, above the trajectory: the loop edge's middle
  // is magenta, the consecutive edge's middle (on the trajectory's band) blue.
  auto at = [&](size_t a, size_t b, const mrpt::img::TColor& c) {
    const double x = 0.5 * (o.nodes[a].x() + o.nodes[b].x()), y = 0.5 * (o.nodes[a].y() + o.nodes[b].y());
    return test::countNear(img, c, int(f.u(x)) - 2, int(f.v(y)) - 2, int(f.u(x)) + 2, int(f.v(y)) + 2);
  };
  EXPECT_GT(at(0, 6, colors::kLoop), 3u);
  EXPECT_GT(at(2, 3, colors::kConsecutive), 3u);
  EXPECT_GT(at(2, 4, colors::kNeighbour) + at(2, 4, colors::kConsecutive), 0u);
  EXPECT_GT(test::countNear(img, colors::kSwitchedOff), 100u);
  // The loop's nodes ringed in magenta around the start and end marks (the ring's top arc,
  // above the marks and the nearly horizontal loop edge); the switched-off loop's (node 1) not.
  auto ring = [&](size_t n) {
    const int u = int(f.u(o.nodes[n].x())), v = int(f.v(o.nodes[n].y()));
    return test::countNear(img, colors::kLoop, u - 8, v - 16, u + 8, v - 10);
  };
  EXPECT_GT(ring(0), 5u);
  EXPECT_GT(ring(6), 5u);
  EXPECT_EQ(ring(1), 0u);
  EXPECT_GT(test::countNear(img, mrpt::img::TColor(255, 185, 90), 0, 0, 1 << 30, 1 << 30, 20), 200u);  // band

  // Scale bar true to the walls; the legend shows each kind drawn.
  const ScaleBar& bar = layout.scale_bar;
  EXPECT_EQ(test::darkRun(img, bar.u, bar.v + 2), bar.pixels);
  EXPECT_NEAR(bar.pixels * m, bar.metres, 0.03 * bar.metres);
  const PixelBox& l = layout.legend;
  for (const auto& c : {colors::kLoop, colors::kConsecutive, colors::kNeighbour, colors::kSwitchedOff,
                        colors::kStart, colors::kEnd, colors::kKeyframe})
    EXPECT_GT(test::countNear(img, c, l.u0, l.v0, l.u1, l.v1, 30), 5u) << int(c.R) << "," << int(c.G) << "," << int(c.B);
  EXPECT_EQ(test::countNear(img, colors::kPrior, l.u0, l.v0, l.u1, l.v1, 20), 0u) << "no prior edge, no entry";
  EXPECT_EQ(test::countNear(img, colors::kByPrediction), 0u) << "no scan marked";

  // Scans the prediction placed: their stretch of the trajectory in violet (shaded like the
  // other ribbons, hence the default tolerance), and an entry.
  o.by_prediction.assign(o.trajectory.size(), false);
  for (int i = 42; i <= 48; i++) o.by_prediction[i] = true;
  const mrpt::img::CImage marked = renderMapImage(g, o, 900, 700, &layout);
  const auto& p = o.trajectory[45];
  EXPECT_GT(test::countNear(marked, colors::kByPrediction, int(f.u(p.x())) - 6, int(f.v(p.y())) - 6,
                            int(f.u(p.x())) + 6, int(f.v(p.y())) + 6),
            10u);
  const auto& q = o.trajectory[15];
  EXPECT_EQ(test::countNear(marked, colors::kByPrediction, int(f.u(q.x())) - 6, int(f.v(q.y())) - 6,
                            int(f.u(q.x())) + 6, int(f.v(q.y())) + 6),
            0u);
  const PixelBox& ml = layout.legend;
  EXPECT_GT(test::countNear(marked, colors::kByPrediction, ml.u0, ml.v0, ml.u1, ml.v1), 5u);
  o.by_prediction.pop_back();
  EXPECT_THROW(renderMapImage(g, o, 900, 700), std::invalid_argument) << "one mark per trajectory pose";
  o.by_prediction.clear();

  o.edges.push_back({1, 9});
  EXPECT_THROW(renderMapImage(g, o, 900, 700), std::invalid_argument);
  EXPECT_THROW(renderMapImage(g, Overlay(), 100, 700), std::invalid_argument);
}

// map.png: the grid with the trajectory, its start and end, axes, a scale bar and a legend,
// checked on the picture's pixels against the walls of a grid whose geometry is known.
#include "picture_test_support.h"
#include "test_support.h"

#include <swslam/map/map_picture.h>

#include <gtest/gtest.h>

using namespace swslam;
using namespace swslam::map;
using mrpt::poses::CPose2D;

namespace
{
Overlay walk()
{
  Overlay o;
  for (int i = 0; i <= 40; i++) o.trajectory.emplace_back(-7 + 0.35 * i, -3 + 0.1 * i + std::sin(0.3 * i), 0);
  return o;
}
}  // namespace

TEST(MapPicture, CellsTrajectoryAndMarksSitWhereTheWallsSayAndTheScaleBarIsTrue)
{
  const auto g = test::wallGrid();
  const Overlay o = walk();
  MapPictureLayout layout;
  const mrpt::img::CImage img = drawMapPicture(g, o, &layout);
  // The room is 20 x 12 m of 0.1 m cells, about 1000 px wide: several pixels per cell.
  ASSERT_GE(layout.pixels_per_cell, 3);
  // Above or below the trajectory, clear of the legend and the scale bar.
  const double y = test::clearRow(layout.view, layout.legend, layout.scale_bar, {4.5, -4.5});
  ASSERT_FALSE(std::isnan(y));
  const auto centre = layout.view.toImage(0, y);
  const test::WallFrame f = test::measureWalls(img, int(centre.x), int(centre.y));
  const double m = f.metresPerPixel();
  EXPECT_NEAR(m, 0.1 / layout.pixels_per_cell, 1e-9) << "20 m between the walls";
  EXPECT_NEAR(f.metresPerPixelY(), m, 1e-9) << "square pixels, 12 m between top and bottom";
  // Free space white, walls black.
  EXPECT_TRUE(test::near(img, int(f.u(-9)), int(f.v(5)), mrpt::img::TColor(255, 255, 255), 5));

  // The start (green) and the end (red) where the trajectory starts and ends.
  const auto& s = o.trajectory.front();
  const auto& e = o.trajectory.back();
  EXPECT_TRUE(test::near(img, int(f.u(s.x())), int(f.v(s.y())), colors::kStart));
  EXPECT_TRUE(test::near(img, int(f.u(e.x())), int(f.v(e.y())), colors::kEnd));
  // The trajectory between them, orange, where its middle pose is.
  const auto& mid = o.trajectory[20];
  size_t orange = test::countNear(img, colors::kTrajectory, int(f.u(mid.x())) - 2, int(f.v(mid.y())) - 2,
                                  int(f.u(mid.x())) + 2, int(f.v(mid.y())) + 2);
  EXPECT_GT(orange, 3u);

  // The scale bar: a nice length, its black bar as many pixels as its metres at the picture's scale.
  const ScaleBar& bar = layout.scale_bar;
  EXPECT_DOUBLE_EQ(bar.metres, niceLength(bar.metres));
  EXPECT_EQ(test::darkRun(img, bar.u, bar.v + 2), bar.pixels);
  EXPECT_NEAR(bar.pixels * m, bar.metres, m);
  EXPECT_GE(bar.metres, 2.0);

  // The legend: a white box holding each of its swatches, hiding neither end.
  const PixelBox& l = layout.legend;
  EXPECT_GT(l.u1 - l.u0, 80);
  EXPECT_GT(test::countNear(img, colors::kStart, l.u0, l.v0, l.u1, l.v1), 20u);
  EXPECT_GT(test::countNear(img, colors::kEnd, l.u0, l.v0, l.u1, l.v1), 20u);
  EXPECT_GT(test::countNear(img, colors::kTrajectory, l.u0, l.v0, l.u1, l.v1), 20u);
  EXPECT_GT(test::countNear(img, mrpt::img::TColor(128, 128, 128), l.u0, l.v0, l.u1, l.v1, 3), 50u);
  for (const auto& p : {s, e}) EXPECT_FALSE(l.contains(f.u(p.x()), f.v(p.y())));

  // Axes: tick labels (dark text) in the left and bottom margins.
  const PictureView& v = layout.view;
  EXPECT_GT(test::countNear(img, mrpt::img::TColor(0, 0, 0), 0, v.top, v.left - 8, v.top + v.height), 40u);
  EXPECT_GT(test::countNear(img, mrpt::img::TColor(0, 0, 0), v.left, v.top + v.height + 8, v.left + v.width,
                            int(img.getHeight()) - 1),
            100u);
}

TEST(MapPicture, ScansPlacedByThePredictionAreDrawnApartWithALegendEntry)
{
  const auto g = test::wallGrid();
  Overlay o = walk();
  MapPictureLayout plain_layout;
  const mrpt::img::CImage plain = drawMapPicture(g, o, &plain_layout);
  EXPECT_EQ(test::countNear(plain, colors::kByPrediction, 0, 0, 1 << 30, 1 << 30, 20), 0u) << "none marked";
  o.by_prediction.assign(o.trajectory.size(), false);
  for (int i = 25; i <= 32; i++) o.by_prediction[i] = true;
  MapPictureLayout layout;
  const mrpt::img::CImage img = drawMapPicture(g, o, &layout);
  auto around = [&](size_t i, const mrpt::img::TColor& c) {
    const auto q = layout.view.toImage(o.trajectory[i].x(), o.trajectory[i].y());
    return test::countNear(img, c, int(q.x) - 3, int(q.y) - 3, int(q.x) + 3, int(q.y) + 3, 20);
  };
  EXPECT_GT(around(29, colors::kByPrediction), 3u);
  EXPECT_EQ(around(29, colors::kTrajectory), 0u);
  EXPECT_GT(around(15, colors::kTrajectory), 3u);
  EXPECT_EQ(around(15, colors::kByPrediction), 0u);
  const PixelBox& l = layout.legend;
  EXPECT_GT(test::countNear(img, colors::kByPrediction, l.u0, l.v0, l.u1, l.v1, 20), 20u);
  EXPECT_GT(l.v1 - l.v0, plain_layout.legend.v1 - plain_layout.legend.v0) << "one more legend row";
  o.by_prediction.resize(3);
  EXPECT_THROW(drawMapPicture(g, o), std::invalid_argument);
}

TEST(MapPicture, AnEmptyGridStillGetsAFramedPicture)
{
  mrpt::maps::COccupancyGridMap2D g(-1, 1, -1, 1, 0.05f);
  MapPictureLayout layout;
  const mrpt::img::CImage img = drawMapPicture(g, Overlay(), &layout);
  EXPECT_GE(layout.view.width, 360);
  EXPECT_EQ(int(img.getWidth()), layout.view.imageWidth());
  EXPECT_TRUE(test::near(img, layout.view.left + layout.view.width / 2, layout.view.top + layout.view.height / 2,
                         mrpt::img::TColor(128, 128, 128), 3));
  const auto dir = test::tempDir("map_picture");
  writeMapPicture(g, Overlay(), dir + "/map.png");
  mrpt::img::CImage back;
  ASSERT_TRUE(back.loadFromFile(dir + "/map.png"));
  EXPECT_EQ(back.getWidth(), img.getWidth());
  Overlay bad;
  bad.edges.push_back({0, 1});
  EXPECT_THROW(drawMapPicture(g, bad), std::invalid_argument);
}

// The annotations both map pictures share: nice lengths, the world-to-image mapping, and a
// legend and scale bar placed where they hide nothing.
#include "picture_test_support.h"

#include <swslam/map/picture_annotations.h>

#include <gtest/gtest.h>

using namespace swslam;
using namespace swslam::map;

TEST(PictureAnnotations, NiceLengthIsOneTwoOrFiveTimesAPowerOfTen)
{
  EXPECT_DOUBLE_EQ(niceLength(1), 1);
  EXPECT_DOUBLE_EQ(niceLength(1.99), 1);
  EXPECT_DOUBLE_EQ(niceLength(2), 2);
  EXPECT_DOUBLE_EQ(niceLength(4.9), 2);
  EXPECT_DOUBLE_EQ(niceLength(7), 5);
  EXPECT_DOUBLE_EQ(niceLength(30), 20);
  EXPECT_DOUBLE_EQ(niceLength(0.3), 0.2);
  EXPECT_DOUBLE_EQ(niceLength(1234), 1000);
}

TEST(PictureAnnotations, ViewMapsWorldToImageNorthUp)
{
  PictureView v;
  v.x0 = -10, v.y1 = 5, v.metres_per_pixel = 0.1, v.width = 200, v.height = 100;
  const auto a = v.toImage(-10, 5);
  EXPECT_DOUBLE_EQ(a.x, kMarginLeft);
  EXPECT_DOUBLE_EQ(a.y, kMarginTop);
  const auto b = v.toImage(0, 0);  // 10 m right, 5 m down
  EXPECT_DOUBLE_EQ(b.x, kMarginLeft + 100);
  EXPECT_DOUBLE_EQ(b.y, kMarginTop + 50);
  EXPECT_EQ(v.imageWidth(), kMarginLeft + 200 + kMarginRight);
}

TEST(PictureAnnotations, LegendAndScaleBarTakeTheEmptyCornersAndTheBarIsTrue)
{
  PictureView v;
  v.x0 = 0, v.y1 = 40, v.metres_per_pixel = 0.05, v.width = 800, v.height = 600;
  mrpt::img::CImage img = framedCanvas(v, "test");
  // Unknown everywhere but a black block filling the top-right quarter.
  img.filledRectangle(v.left, v.top, v.left + v.width - 1, v.top + v.height - 1, mrpt::img::TColor(128, 128, 128));
  img.filledRectangle(v.left + v.width / 2, v.top, v.left + v.width - 1, v.top + v.height / 2, mrpt::img::TColor(0, 0, 0));
  PixelBox legend;
  const ScaleBar bar = drawLegendAndScaleBar(img, v, mapLegend(), &legend);
  EXPECT_LT(legend.u1, v.left + v.width / 2) << "top-left, not over the block";
  EXPECT_LT(legend.v1, v.top + v.height / 2);
  EXPECT_GT(bar.box.v0, v.top + v.height / 2) << "a bottom corner";
  EXPECT_FALSE(bar.box.u0 <= legend.u1 && bar.box.v0 <= legend.v1) << "apart from the legend";
  // 800 px of 0.05 m = 40 m wide: a quarter is 10 m, 200 px.
  EXPECT_DOUBLE_EQ(bar.metres, 10);
  EXPECT_EQ(bar.pixels, 200);
  EXPECT_EQ(test::darkRun(img, bar.u, bar.v + 2), 200);
  EXPECT_EQ(test::darkRun(img, bar.u, bar.v + 7), 0) << "6 px high";
  // Every legend swatch shows in the legend's box.
  for (const auto& e : mapLegend())
    if (e.symbol != LegendEntry::Symbol::Swatch)
      EXPECT_GT(test::countNear(img, e.color, legend.u0, legend.v0, legend.u1, legend.v1, 20), 5u) << e.label;
}

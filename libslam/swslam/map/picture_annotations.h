#pragma once
// What makes a map picture (map.png, render.png) read without the docs: axes ticked in metres,
// a scale bar, start and end marks on the trajectory and a legend, drawn with MRPT's bitmap
// fonts into an mrpt::img::CImage (no window, no display). Both pictures are a plot area, north
// (+y) up, inside margins that hold the title and the axis labels.

#include <swslam/map/overlay.h>

#include <mrpt/img/CImage.h>
#include <mrpt/img/TColor.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>

#include <string>
#include <vector>

namespace swslam::map
{
/** Margins around the plot area [px]: title above, y labels left, x labels below. */
constexpr int kMarginLeft = 64, kMarginRight = 16, kMarginTop = 30, kMarginBottom = 46;

/** The plot area of a picture and the world it shows: image pixel (u, v), with u to the right
 * and v down, shows world (x0 + (u - left + 0.5) m, y1 - (v - top + 0.5) m) with m =
 * metres_per_pixel: pixels are square and the picture is north up. */
struct PictureView
{
  double x0 = 0, y1 = 0;  ///< world [m] of the plot area's top-left corner
  double metres_per_pixel = 1;
  int left = kMarginLeft, top = kMarginTop;  ///< plot area's top-left pixel
  int width = 0, height = 0;                 ///< plot area [px]

  /** The image position of world (x, y) [px, fractional; pixel centres at +0.5]. */
  mrpt::math::TPoint2D toImage(double x, double y) const;
  int imageWidth() const { return left + width + kMarginRight; }
  int imageHeight() const { return top + height + kMarginBottom; }
};

/** World rectangle [m]. */
struct Extent
{
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(double x, double y);
  bool valid() const { return x1 >= x0 && y1 >= y0; }
};

/** What a picture frames: the observed cells (not at the prior), the trajectory and the nodes;
 * the whole grid if none. */
Extent framedExtent(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay);

/** The largest of 1, 2 and 5 times a power of ten not above `at_most` (> 0). */
double niceLength(double at_most);

/** A white image of the view's size with a frame round the plot area, ticks every nice step
 * along both axes labelled in metres ("x [m]", "y [m]") and `title` above. */
mrpt::img::CImage framedCanvas(const PictureView& view, const std::string& title);

/** The ticks and their labels again (after the plot area was painted). */
void drawAxes(mrpt::img::CImage& img, const PictureView& view);

/** A filled disc and a filled square, clipped to the image. */
void fillDisc(mrpt::img::CImage& img, int u, int v, int radius, const mrpt::img::TColor& color);
void fillSquare(mrpt::img::CImage& img, int u, int v, int half, const mrpt::img::TColor& color);

/** Colours shared by both pictures. */
namespace colors
{
const mrpt::img::TColor kTrajectory(255, 140, 0), kByPrediction(120, 60, 200), kStart(0, 170, 0), kEnd(220, 0, 0),
    kKeyframe(20, 20, 120),
    kConsecutive(30, 80, 230), kNeighbour(0, 175, 190), kLoop(230, 0, 230), kPrior(140, 90, 30),
    kSwitchedOff(210, 0, 0), kText(0, 0, 0), kBox(255, 255, 255), kBoxBorder(90, 90, 90);
}

/** Start (green disc, radius 7 px) and end (red square, 15 px) of the trajectory. */
void drawStartAndEnd(mrpt::img::CImage& img, const PictureView& view,
                     const std::vector<mrpt::poses::CPose2D>& trajectory);

/** A rectangle of the image [px], inclusive corners. */
struct PixelBox
{
  int u0 = 0, v0 = 0, u1 = -1, v1 = -1;
  bool contains(double u, double v) const { return u >= u0 && u <= u1 && v >= v0 && v <= v1; }
};

struct ScaleBar
{
  double metres = 0;   ///< the stated length
  int pixels = 0;      ///< its length in the image
  int u = 0, v = 0;    ///< left end, top row of the bar
  PixelBox box;        ///< its white box
};

struct LegendEntry
{
  enum class Symbol
  {
    Line,    ///< a line of `width` px
    Dashed,  ///< a dashed line
    Dot,     ///< a small square `width` px wide (keyframes)
    Start,   ///< the start mark
    End,     ///< the end mark
    Swatch   ///< a filled square with a thin border (map cells)
  };
  std::string label;
  mrpt::img::TColor color;
  Symbol symbol = Symbol::Line;
  int width = 2;
};

/** The legend box in the corner of the plot area that hides the least of the picture (pixels
 * other than unknown-grey: map, trajectory, graph, marks), then the scale bar (a nice length
 * near a quarter of the plot's width, labelled in metres) in the emptier bottom corner left.
 * Returns the scale bar; `legend` (if given) receives the legend's box. */
ScaleBar drawLegendAndScaleBar(mrpt::img::CImage& img, const PictureView& view,
                               const std::vector<LegendEntry>& entries, PixelBox* legend = nullptr);

/** The legend of the map cells (free, occupied, unknown), the trajectory and its ends. */
std::vector<LegendEntry> mapLegend();

}  // namespace swslam::map

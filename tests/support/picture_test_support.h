#pragma once
// Helpers shared by the map picture tests (map.png, render.png): a grid with walls at known
// places, and measurements taken on the picture itself (never from the drawing code's layout).

#include <swslam/map/picture_annotations.h>

#include <mrpt/img/CImage.h>
#include <mrpt/img/TColor.h>
#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cmath>
#include <cstdlib>

namespace swslam::test
{
/** A 0.1 m grid over [-12, 12] x [-8, 8] m, free inside a rectangle of walls: the left wall's
 * cells start at x = -10 m, the right wall's at x = +10 m, the top wall's at y = +6 m, the
 * bottom wall's at y = -6 m; unknown outside. */
inline mrpt::maps::COccupancyGridMap2D wallGrid()
{
  mrpt::maps::COccupancyGridMap2D g(-12, 12, -8, 8, 0.1f);
  for (int cy = 0; cy < int(g.getSizeY()); cy++)
    for (int cx = 0; cx < int(g.getSizeX()); cx++)
    {
      const double x = g.idx2x(cx), y = g.idx2y(cy);
      const bool wall_x = std::abs(std::abs(x) - 10.05) < 0.01 && std::abs(y) < 6.1;
      const bool wall_y = std::abs(std::abs(y) - 6.05) < 0.01 && std::abs(x) < 10.1;
      if (wall_x || wall_y)
        g.setCell(cx, cy, 0.0f);
      else if (std::abs(x) < 10 && std::abs(y) < 6)
        g.setCell(cx, cy, 1.0f);
    }
  return g;
}

inline bool near(const mrpt::img::CImage& img, int u, int v, const mrpt::img::TColor& c, int tol = 40)
{
  if (u < 0 || v < 0 || u >= int(img.getWidth()) || v >= int(img.getHeight())) return false;
  const uint8_t* px = img(u, v);  // BGR
  return std::abs(px[2] - c.R) < tol && std::abs(px[1] - c.G) < tol && std::abs(px[0] - c.B) < tol;
}

/** The pixels within `tol` of `c` in the box [u0, u1] x [v0, v1] (inclusive, clipped). */
inline size_t countNear(const mrpt::img::CImage& img, const mrpt::img::TColor& c, int u0 = 0, int v0 = 0,
                        int u1 = 1 << 30, int v1 = 1 << 30, int tol = 40)
{
  size_t n = 0;
  for (int v = std::max(0, v0); v <= std::min(v1, int(img.getHeight()) - 1); v++)
    for (int u = std::max(0, u0); u <= std::min(u1, int(img.getWidth()) - 1); u++) n += near(img, u, v, c, tol);
  return n;
}

/** The first column from `u_from` stepping by `du` on row `v` whose pixel is dark (a wall). */
inline int firstDark(const mrpt::img::CImage& img, int u_from, int du, int v)
{
  for (int u = u_from; u >= 0 && u < int(img.getWidth()); u += du)
    if (near(img, u, v, mrpt::img::TColor(0, 0, 0), 70)) return u;
  return -1;
}
/** The same along a column. */
inline int firstDarkRow(const mrpt::img::CImage& img, int u, int v_from, int dv)
{
  for (int v = v_from; v >= 0 && v < int(img.getHeight()); v += dv)
    if (near(img, u, v, mrpt::img::TColor(0, 0, 0), 70)) return v;
  return -1;
}

/** The length of the run of dark pixels on row `v` starting at column `u`. */
inline int darkRun(const mrpt::img::CImage& img, int u, int v)
{
  int n = 0;
  while (near(img, u + n, v, mrpt::img::TColor(0, 0, 0), 60)) n++;
  return n;
}

/** Where the walls of wallGrid() are in a picture: the image position of world (x, y) and
 * the metres per pixel, measured from the walls' inner edges on the row and column through
 * the picture point (u_in, v_in) inside the room. */
struct WallFrame
{
  double u_left = 0, u_right = 0, v_top = 0, v_bottom = 0;  ///< inner edges: x = -10, +10, y = +6, -6
  double metresPerPixel() const { return 20.0 / (u_right - u_left); }
  double metresPerPixelY() const { return 12.0 / (v_bottom - v_top); }
  double u(double x) const { return u_left + (x + 10.0) / metresPerPixel(); }
  double v(double y) const { return v_top + (6.0 - y) / metresPerPixel(); }
};

/** Measures the walls' inner edges from a point inside the room: the first dark pixels to
 * the left, right, top and bottom. */
inline WallFrame measureWalls(const mrpt::img::CImage& img, int u_in, int v_in)
{
  WallFrame f;
  f.u_left = firstDark(img, u_in, -1, v_in) + 1;   // first free column's left edge
  f.u_right = firstDark(img, u_in, +1, v_in);      // the wall's left edge
  f.v_top = firstDarkRow(img, u_in, v_in, -1) + 1;
  f.v_bottom = firstDarkRow(img, u_in, v_in, +1);
  return f;
}

/** The first of `ys` [m] whose picture row (+-3 px) crosses neither the legend nor the scale
 * bar: where the walls can be measured. NaN if none. */
inline double clearRow(const map::PictureView& view, const map::PixelBox& legend, const map::ScaleBar& bar,
                       std::initializer_list<double> ys)
{
  for (const double y : ys)
  {
    const double v = view.toImage(0, y).y;
    const auto crosses = [&](const map::PixelBox& b) { return v >= b.v0 - 3 && v <= b.v1 + 3; };
    if (!crosses(legend) && !crosses(bar.box)) return y;
  }
  return std::nan("");
}

}  // namespace swslam::test

#include <swslam/map/picture_annotations.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace swslam::map
{
namespace
{
// MRPT's bitmap fonts: ticks and legend in 9x15 (9 px per character, 15 px high).
constexpr int kCharWidth = 9, kCharHeight = 15;
const char* const kFont = "9x15";

int textWidth(const std::string& s) { return kCharWidth * static_cast<int>(s.size()); }

/** A tick label: as many decimals as the step needs ("-20", "2.5"). */
std::string tickLabel(double value, double step)
{
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, std::abs(value) < 0.5 * step * 1e-6 ? 0.0 : value);
  return buf;
}

/** The world values of the ticks along [lo, hi]. */
std::vector<double> ticks(double lo, double hi, double step)
{
  std::vector<double> t;
  for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) t.push_back(v);
  return t;
}

/** The tick step: a nice length giving 4 to 10 ticks over `span` metres. */
double tickStep(double span) { return niceLength(span / 4); }

void text(mrpt::img::CImage& img, int u, int v, const std::string& s, const mrpt::img::TColor& color = colors::kText)
{
  img.selectTextFont(kFont);
  img.textOut(u, v, s, color);
}

void whiteBox(mrpt::img::CImage& img, const PixelBox& b)
{
  img.filledRectangle(b.u0, b.v0, b.u1, b.v1, colors::kBox);
  img.rectangle(b.u0, b.v0, b.u1, b.v1, colors::kBoxBorder, 1);
}

void drawSymbol(mrpt::img::CImage& img, const LegendEntry& e, int u0, int vc, int length)
{
  using S = LegendEntry::Symbol;
  const int half = std::max(0, (e.width - 1) / 2);
  switch (e.symbol)
  {
    case S::Line: img.filledRectangle(u0, vc - half, u0 + length, vc - half + e.width - 1, e.color); break;
    case S::Dashed:
      for (int u = u0; u < u0 + length; u += 8)
        img.filledRectangle(u, vc - half, std::min(u + 4, u0 + length), vc - half + e.width - 1, e.color);
      break;
    case S::Dot: fillSquare(img, u0 + length / 2, vc, e.width / 2, e.color); break;
    case S::Start:
      fillDisc(img, u0 + length / 2, vc, 7, colors::kText);
      fillDisc(img, u0 + length / 2, vc, 5, e.color);
      break;
    case S::End:
      fillSquare(img, u0 + length / 2, vc, 7, colors::kText);
      fillSquare(img, u0 + length / 2, vc, 5, e.color);
      break;
    case S::Swatch:
      img.filledRectangle(u0 + length / 2 - 6, vc - 6, u0 + length / 2 + 6, vc + 6, e.color);
      img.rectangle(u0 + length / 2 - 6, vc - 6, u0 + length / 2 + 6, vc + 6, colors::kBoxBorder, 1);
      break;
  }
}

/** The four corner boxes of a w x h box inside the plot area: top-right, top-left,
 * bottom-right, bottom-left. */
std::array<PixelBox, 4> corners(const PictureView& view, int w, int h)
{
  const int inset = 8;
  const int l = view.left + inset, r = view.left + view.width - 1 - inset;
  const int t = view.top + inset, b = view.top + view.height - 1 - inset;
  return {PixelBox{r - w + 1, t, r, t + h - 1}, PixelBox{l, t, l + w - 1, t + h - 1},
          PixelBox{r - w + 1, b - h + 1, r, b}, PixelBox{l, b - h + 1, l + w - 1, b}};
}

/** What a box would hide: its pixels that are not unknown-grey (map content, trajectory,
 * graph, marks). */
size_t hidden(const mrpt::img::CImage& img, const PixelBox& box)
{
  size_t n = 0;
  for (int v = std::max(0, box.v0); v <= std::min(box.v1, int(img.getHeight()) - 1); v++)
    for (int u = std::max(0, box.u0); u <= std::min(box.u1, int(img.getWidth()) - 1); u++)
    {
      const uint8_t* px = img(u, v);
      n += std::abs(px[0] - 128) > 12 || std::abs(px[1] - 128) > 12 || std::abs(px[2] - 128) > 12;
    }
  return n;
}
}  // namespace

mrpt::math::TPoint2D PictureView::toImage(double x, double y) const
{
  return {left + (x - x0) / metres_per_pixel, top + (y1 - y) / metres_per_pixel};
}

void Extent::add(double x, double y)
{
  x0 = std::min(x0, x), x1 = std::max(x1, x);
  y0 = std::min(y0, y), y1 = std::max(y1, y);
}

Extent framedExtent(const mrpt::maps::COccupancyGridMap2D& grid, const Overlay& overlay)
{
  Extent e;
  const auto& raw = grid.getRawMap();
  const unsigned w = grid.getSizeX();
  const double r = 0.5 * grid.getResolution();
  for (size_t i = 0; i < raw.size(); i++)
    if (raw[i] != 0)
    {
      const double x = grid.idx2x(static_cast<int>(i % w)), y = grid.idx2y(static_cast<int>(i / w));
      e.add(x - r, y - r), e.add(x + r, y + r);
    }
  for (const auto& p : overlay.trajectory) e.add(p.x(), p.y());
  for (const auto& p : overlay.nodes) e.add(p.x(), p.y());
  if (!e.valid())
  {
    e.add(grid.getXMin(), grid.getYMin());
    e.add(grid.getXMax(), grid.getYMax());
  }
  return e;
}

double niceLength(double at_most)
{
  const double p = std::pow(10.0, std::floor(std::log10(at_most) + 1e-9));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= at_most * (1 + 1e-9)) return m * p;
  return p;
}

void drawAxes(mrpt::img::CImage& img, const PictureView& view)
{
  const int l = view.left, t = view.top, r = view.left + view.width - 1, b = view.top + view.height - 1;
  const auto& black = colors::kText;
  img.rectangle(l - 1, t - 1, r + 1, b + 1, black, 1);
  const double m = view.metres_per_pixel;
  const double x_lo = view.x0, x_hi = view.x0 + view.width * m;
  const double y_lo = view.y1 - view.height * m, y_hi = view.y1;
  const double step = tickStep(std::max(x_hi - x_lo, y_hi - y_lo));
  for (double x : ticks(x_lo, x_hi, step))
  {
    const int u = static_cast<int>(std::lround(view.toImage(x, 0).x));
    img.line(u, b + 2, u, b + 7, black, 1);
    const std::string s = tickLabel(x, step);
    text(img, u - textWidth(s) / 2, b + 9, s);
  }
  for (double y : ticks(y_lo, y_hi, step))
  {
    const int v = static_cast<int>(std::lround(view.toImage(0, y).y));
    img.line(l - 7, v, l - 2, v, black, 1);
    const std::string s = tickLabel(y, step);
    text(img, l - 9 - textWidth(s), v - kCharHeight / 2, s);
  }
  text(img, l + view.width / 2 - textWidth("x [m]") / 2, b + 9 + kCharHeight + 4, "x [m]");
  text(img, std::max(0, l - 9 - textWidth("y [m]")), t - kCharHeight - 4, "y [m]");
}

mrpt::img::CImage framedCanvas(const PictureView& view, const std::string& title)
{
  mrpt::img::CImage img(view.imageWidth(), view.imageHeight(), mrpt::img::CH_RGB);
  img.filledRectangle(0, 0, view.imageWidth() - 1, view.imageHeight() - 1, mrpt::img::TColor(255, 255, 255));
  text(img, view.left, 6, title);
  drawAxes(img, view);
  return img;
}

void fillDisc(mrpt::img::CImage& img, int u, int v, int radius, const mrpt::img::TColor& color)
{
  for (int dv = -radius; dv <= radius; dv++)
  {
    const int half = static_cast<int>(std::floor(std::sqrt(double(radius * radius - dv * dv)) + 0.3));
    img.filledRectangle(u - half, v + dv, u + half, v + dv, color);
  }
}

void fillSquare(mrpt::img::CImage& img, int u, int v, int half, const mrpt::img::TColor& color)
{
  img.filledRectangle(u - half, v - half, u + half, v + half, color);
}

void drawStartAndEnd(mrpt::img::CImage& img, const PictureView& view,
                     const std::vector<mrpt::poses::CPose2D>& trajectory)
{
  if (trajectory.empty()) return;
  // The end first: where the run ends at its start, the start's disc sits inside the end's square.
  const auto e = view.toImage(trajectory.back().x(), trajectory.back().y());
  const auto s = view.toImage(trajectory.front().x(), trajectory.front().y());
  const int eu = static_cast<int>(std::floor(e.x)), ev = static_cast<int>(std::floor(e.y));
  const int su = static_cast<int>(std::floor(s.x)), sv = static_cast<int>(std::floor(s.y));
  fillSquare(img, eu, ev, 9, colors::kText);
  fillSquare(img, eu, ev, 7, colors::kEnd);
  fillDisc(img, su, sv, 7, colors::kText);
  fillDisc(img, su, sv, 5, colors::kStart);
}

std::vector<LegendEntry> mapLegend()
{
  using S = LegendEntry::Symbol;
  return {{"free", mrpt::img::TColor(255, 255, 255), S::Swatch, 0},
          {"occupied", mrpt::img::TColor(0, 0, 0), S::Swatch, 0},
          {"unknown", mrpt::img::TColor(128, 128, 128), S::Swatch, 0},
          {"trajectory", colors::kTrajectory, S::Line, 3},
          {"start", colors::kStart, S::Start, 0},
          {"end", colors::kEnd, S::End, 0}};
}

ScaleBar drawLegendAndScaleBar(mrpt::img::CImage& img, const PictureView& view,
                               const std::vector<LegendEntry>& entries, PixelBox* legend)
{
  // The legend: one row per entry, symbol then label.
  const int row = kCharHeight + 5, symbol = 30, pad = 7;
  size_t longest = 0;
  for (const auto& e : entries) longest = std::max(longest, e.label.size());
  const int lw = pad + symbol + 8 + kCharWidth * static_cast<int>(longest) + pad;
  const int lh = 2 * pad + row * static_cast<int>(entries.size()) - 5;
  const auto legend_corners = corners(view, lw, lh);
  size_t best = 0;
  for (size_t i = 1; i < legend_corners.size(); i++)
    if (hidden(img, legend_corners[i]) < hidden(img, legend_corners[best])) best = i;
  const PixelBox lbox = legend_corners[best];
  if (!entries.empty())
  {
    whiteBox(img, lbox);
    for (size_t i = 0; i < entries.size(); i++)
    {
      const int v = lbox.v0 + pad + static_cast<int>(i) * row;
      drawSymbol(img, entries[i], lbox.u0 + pad, v + kCharHeight / 2, symbol);
      text(img, lbox.u0 + pad + symbol + 8, v, entries[i].label);
    }
  }
  if (legend) *legend = lbox;

  // The scale bar: a nice length near a quarter of the plot's width.
  ScaleBar bar;
  bar.metres = niceLength(0.25 * view.width * view.metres_per_pixel);
  bar.pixels = static_cast<int>(std::lround(bar.metres / view.metres_per_pixel));
  char label[32];
  std::snprintf(label, sizeof(label), "%g m", bar.metres);
  const int bw = std::max(bar.pixels, textWidth(label)) + 2 * pad, bh = 2 * pad + kCharHeight + 4 + 6;
  const auto bar_corners = corners(view, bw, bh);
  // Bottom-left or bottom-right, whichever the legend leaves and hides less.
  size_t pick = 3;
  if (best == 3 || (best != 2 && hidden(img, bar_corners[2]) < hidden(img, bar_corners[3]))) pick = 2;
  bar.box = bar_corners[pick];
  whiteBox(img, bar.box);
  bar.u = bar.box.u0 + (bw - bar.pixels) / 2;
  bar.v = bar.box.v1 - pad - 6 + 1;
  img.filledRectangle(bar.u, bar.v, bar.u + bar.pixels - 1, bar.v + 5, colors::kText);
  text(img, bar.box.u0 + (bw - textWidth(label)) / 2, bar.box.v0 + pad, label);
  return bar;
}

}  // namespace swslam::map

#include <swslam/sim/writer.h>

#include <swslam/common/atomic_file.h>
#include <swslam/common/image_file.h>

#include <mrpt/core/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace swslam::sim
{
std::string formatMrptGroundTruth(const std::vector<common::StampedPose>& poses)
{
  std::string s;
  for (const auto& p : poses)
    s += mrpt::format("%.6f %.6f %.6f %.6f\n", p.t, p.pose.x(), p.pose.y(), p.pose.phi());
  return s;
}

void writeMrptGroundTruth(const std::string& path, const std::vector<common::StampedPose>& poses)
{
  common::writeTextAtomically(path, formatMrptGroundTruth(poses));
}

namespace
{
using mrpt::img::TColor;

class Painter
{
 public:
  Painter(const Box& b, int max_side)
      : box_(b), scale_(max_side / std::max(b.max_x - b.min_x, b.max_y - b.min_y))
  {
    img_ = mrpt::img::CImage(col(b.max_x) + 1, row(b.min_y) + 1, mrpt::img::CH_RGB);
  }
  int col(double x) const { return static_cast<int>(std::lround((x - box_.min_x) * scale_)); }
  int row(double y) const { return static_cast<int>(std::lround((box_.max_y - y) * scale_)); }
  Eigen::Vector2d center(int c, int r) const
  {
    return {box_.min_x + (c + 0.5) / scale_, box_.max_y - (r + 0.5) / scale_};
  }
  void disc(const Eigen::Vector2d& p, double radius, const TColor& color)
  {
    const int r = std::max(1, static_cast<int>(std::lround(radius * scale_)));
    const int c0 = col(p.x()), r0 = row(p.y());
    for (int dy = -r; dy <= r; dy++)
      for (int dx = -r; dx <= r; dx++)
        if (dx * dx + dy * dy <= r * r) img_.setPixel(c0 + dx, r0 + dy, color);
  }
  void line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const TColor& color, int width)
  {
    img_.line(col(a.x()), row(a.y()), col(b.x()), row(b.y()), color, width);
  }
  mrpt::img::CImage img_;

 private:
  Box box_;
  double scale_;
};

TColor colorOf(ShapeKind k)
{
  switch (k)
  {
    case ShapeKind::Bank: return {110, 80, 40};
    case ShapeKind::Rock: return {120, 120, 120};
    case ShapeKind::Trunk: return {20, 90, 20};
    case ShapeKind::Bush: return {110, 190, 80};
    case ShapeKind::Reed: return {150, 150, 40};
    case ShapeKind::Wall: return {60, 60, 60};
  }
  return {0, 0, 0};
}
}  // namespace

mrpt::img::CImage drawWorld(const World& world, const std::vector<Eigen::Vector2d>& path,
                            int max_side)
{
  Painter p(world.bounds, max_side);
  const TColor water(150, 190, 230), land(225, 215, 180);
  for (int r = 0; r < static_cast<int>(p.img_.getHeight()); r++)
    for (int c = 0; c < static_cast<int>(p.img_.getWidth()); c++)
      p.img_.setPixel(c, r, world.isWater(p.center(c, r)) ? water : land);
  for (const auto& s : world.shapes)
  {
    if (s.isCircle())
      p.disc(s.a, s.radius, colorOf(s.kind));
    else
      p.line(s.a, s.b, colorOf(s.kind), 2);
  }
  for (size_t i = 1; i < path.size(); i++) p.line(path[i - 1], path[i], TColor(220, 30, 30), 2);
  if (!path.empty())
  {
    p.disc(path.front(), 1.5, TColor(255, 255, 255));
    p.disc(path.front(), 0.7, TColor(220, 30, 30));
  }
  return p.img_;
}

void writeWorldPicture(const std::string& png_path, const World& world,
                       const std::vector<Eigen::Vector2d>& path)
{
  const mrpt::img::CImage img = drawWorld(world, path);
  common::writeImageAtomically(png_path, img);
}

}  // namespace swslam::sim

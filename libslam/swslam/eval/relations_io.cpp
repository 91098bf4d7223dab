#include <swslam/eval/relations_io.h>

#include <swslam/common/number_rows.h>

#include <mrpt/core/format.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace swslam::eval
{
namespace
{
/** z, roll and pitch below this count as planar (metres / radians). */
constexpr double kPlanarTolerance = 1e-6;
}  // namespace

std::vector<Relation> readRelations(const std::string& path)
{
  std::vector<Relation> out;
  for (const auto& v : common::readNumberRows<8>(path, "relations", "t1 t2 x y z roll pitch yaw"))
  {
    const bool planar = std::abs(v[4]) < kPlanarTolerance &&
                        std::abs(v[5]) < kPlanarTolerance && std::abs(v[6]) < kPlanarTolerance;
    out.push_back({v[0], v[1], mrpt::poses::CPose2D(v[2], v[3], v[7]), planar});
  }
  return out;
}

std::string formatRelations(const std::vector<Relation>& relations)
{
  // No length limit (mrpt::format): two "%.6f" times of up to 1e308 s overflowed a fixed
  // buffer, which cut the line.
  std::string s = "# timestamp1 timestamp2 x y z roll pitch yaw\n";
  for (const auto& r : relations)
    s += mrpt::format("%.6f %.6f %.9g %.9g 0 0 0 %.9g\n", r.t1, r.t2, r.delta.x(), r.delta.y(),
                      r.delta.phi());
  return s;
}

}  // namespace swslam::eval

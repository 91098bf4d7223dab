#include <swslam/eval/relations_io.h>

#include <swslam/common/number_rows.h>

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
  std::string s = "# timestamp1 timestamp2 x y z roll pitch yaw\n";
  char buf[256];
  for (const auto& r : relations)
  {
    std::snprintf(buf, sizeof(buf), "%.6f %.6f %.9g %.9g 0 0 0 %.9g\n", r.t1, r.t2,
                  r.delta.x(), r.delta.y(), r.delta.phi());
    s += buf;
  }
  return s;
}

}  // namespace swslam::eval

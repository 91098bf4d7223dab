#include "swslam/eval/relations.h"

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
  std::ifstream f(path);
  if (!f) throw std::runtime_error("relations: cannot open '" + path + "'");
  std::vector<Relation> out;
  std::string line;
  size_t line_no = 0;
  while (std::getline(f, line))
  {
    line_no++;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream ss(line);
    double v[8];
    bool ok = true;
    for (double& x : v) ok = ok && (ss >> x) && std::isfinite(x);
    std::string rest;
    if (!ok || (ss >> rest))
      throw std::runtime_error("relations: '" + path + "' line " + std::to_string(line_no) +
                               ": expected 8 finite numbers 't1 t2 x y z roll pitch yaw'");
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

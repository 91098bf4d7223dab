#include "swslam/tum_io.h"

#include "swslam/atomic_file.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace swslam
{
std::vector<StampedPose> readTum(const std::string& path)
{
  std::ifstream f(path);
  if (!f) throw std::runtime_error("tum: cannot open '" + path + "'");
  std::vector<StampedPose> out;
  std::string line;
  size_t line_no = 0;
  while (std::getline(f, line))
  {
    line_no++;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream ss(line);
    double t, x, y, z, qx, qy, qz, qw;
    if (!(ss >> t >> x >> y >> z >> qx >> qy >> qz >> qw) || !std::isfinite(t) ||
        !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(qz) || !std::isfinite(qw))
      throw std::runtime_error("tum: '" + path + "' line " + std::to_string(line_no) +
                               ": expected 8 finite numbers 't x y z qx qy qz qw'");
    const double yaw = std::atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz));
    out.push_back({t, mrpt::poses::CPose2D(x, y, yaw)});
  }
  return out;
}

std::string formatTum(const std::vector<StampedPose>& poses)
{
  std::string s = "# timestamp x y z qx qy qz qw\n";
  char buf[256];
  for (const auto& p : poses)
  {
    const double h = 0.5 * p.pose.phi();
    std::snprintf(buf, sizeof(buf), "%.6f %.9g %.9g 0 0 0 %.9g %.9g\n", p.t, p.pose.x(),
                  p.pose.y(), std::sin(h), std::cos(h));
    s += buf;
  }
  return s;
}

void writeTum(const std::string& path, const std::vector<StampedPose>& poses)
{
  writeTextAtomically(path, formatTum(poses));
}

}  // namespace swslam

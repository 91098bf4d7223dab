#include "swslam/tum_io.h"

#include "swslam/atomic_file.h"
#include "swslam/number_rows.h"

#include <cmath>
#include <cstdio>

namespace swslam
{
std::vector<StampedPose> readTum(const std::string& path)
{
  std::vector<StampedPose> out;
  for (const auto& [t, x, y, z, qx, qy, qz, qw] :
       readNumberRows<8>(path, "tum", "t x y z qx qy qz qw"))
  {
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

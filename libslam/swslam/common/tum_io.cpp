#include <swslam/common/tum_io.h>

#include <swslam/common/atomic_file.h>
#include <swslam/common/number_rows.h>

#include <mrpt/core/format.h>

#include <cmath>
#include <cstdio>

namespace swslam::common
{
std::vector<StampedPose> readTum(const std::string& path)
{
  // What makes a row no pose: a position beyond kMaxTumCoordinate is no trajectory (and its
  // squares overflow an error sum: an ATE of inf); a quaternion far from unit length is no
  // rotation (all zeros read as yaw 0, silently), 1% leaving room for files written with few
  // decimals.
  auto row_problem = [](const std::array<double, 8>& r) -> std::string {
    char buf[120];
    for (int k = 1; k <= 3; k++)
      if (std::abs(r[k]) > kMaxTumCoordinate)
      {
        std::snprintf(buf, sizeof(buf), "position %c = %g m is beyond %g m", "txyz"[k], r[k], kMaxTumCoordinate);
        return buf;
      }
    const double norm = std::sqrt(r[4] * r[4] + r[5] * r[5] + r[6] * r[6] + r[7] * r[7]);
    if (std::abs(norm - 1) <= 0.01) return {};
    std::snprintf(buf, sizeof(buf), "quaternion (%g %g %g %g) has norm %g, not 1", r[4], r[5], r[6], r[7], norm);
    return buf;
  };
  const auto rows = readNumberRows<8>(path, "tum", "t x y z qx qy qz qw", row_problem);
  std::vector<StampedPose> out;
  out.reserve(rows.size());
  for (const auto& [t, x, y, z, qx, qy, qz, qw] : rows)
  {
    const double yaw = std::atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz));
    out.push_back({t, mrpt::poses::CPose2D(x, y, yaw)});
  }
  return out;
}

std::string formatTum(const std::vector<StampedPose>& poses)
{
  // mrpt::format has no length limit: "%.6f" of a (finite) time up to 1e308 s takes 316
  // characters, and a fixed buffer cut the line, which no reader could load back.
  std::string s = "# timestamp x y z qx qy qz qw\n";
  for (const auto& p : poses)
  {
    const double h = 0.5 * p.pose.phi();
    s += mrpt::format("%.6f %.9g %.9g 0 0 0 %.9g %.9g\n", p.t, p.pose.x(), p.pose.y(),
                      std::sin(h), std::cos(h));
  }
  return s;
}

void writeTum(const std::string& path, const std::vector<StampedPose>& poses)
{
  writeTextAtomically(path, formatTum(poses));
}

}  // namespace swslam::common

#pragma once
// Small synthetic trajectories and slow, obviously-correct SE(2) algebra for the eval tests.

#include <swslam/eval/association.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <random>
#include <vector>

namespace swslam::test
{
/** Homogeneous 3x3 matrix of the pose (x, y, phi). */
inline Eigen::Matrix3d homogeneous(const mrpt::poses::CPose2D& p)
{
  Eigen::Matrix3d m;
  m << std::cos(p.phi()), -std::sin(p.phi()), p.x(), std::sin(p.phi()), std::cos(p.phi()), p.y(),
      0, 0, 1;
  return m;
}

/** Translation norm and |angle| of a homogeneous matrix. */
inline double transNorm(const Eigen::Matrix3d& m) { return m.block<2, 1>(0, 2).norm(); }
inline double rotAngle(const Eigen::Matrix3d& m) { return std::abs(std::atan2(m(1, 0), m(0, 0))); }

/** A wandering planar path: n poses at 10 Hz from t0, steps of ~0.3 m, smooth turns. */
inline std::vector<common::StampedPose> wanderingPath(size_t n, double t0, unsigned seed)
{
  std::mt19937 rng(seed);
  std::normal_distribution<double> turn(0, 0.15);
  std::vector<common::StampedPose> out;
  double x = 0, y = 0, a = 0.3;
  for (size_t i = 0; i < n; i++)
  {
    out.push_back({t0 + 0.1 * i, {x, y, a}});
    a += turn(rng);
    x += 0.3 * std::cos(a);
    y += 0.3 * std::sin(a);
  }
  return out;
}

/** Every pose of `path` moved by the rigid transform T (T (+) pose). */
inline std::vector<common::StampedPose> transformed(const std::vector<common::StampedPose>& path,
                                            const mrpt::poses::CPose2D& T)
{
  auto out = path;
  for (auto& p : out) p.pose = T + p.pose;
  return out;
}

/** Pose i of `est` paired with pose i of `gt` (same lengths), without any association. */
inline std::vector<eval::PosePair> pairUp(const std::vector<common::StampedPose>& est,
                                          const std::vector<common::StampedPose>& gt)
{
  std::vector<eval::PosePair> out;
  for (size_t i = 0; i < gt.size(); i++)
    out.push_back({est[i].t, gt[i].t, est[i].pose, gt[i].pose});
  return out;
}

}  // namespace swslam::test

#include <swslam/eval/se2_alignment.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

namespace swslam::eval
{
mrpt::poses::CPose2D alignSE2(const std::vector<Eigen::Vector2d>& a,
                              const std::vector<Eigen::Vector2d>& b)
{
  if (a.size() != b.size() || a.empty())
    throw std::invalid_argument("alignSE2: need two non-empty point sets of equal size");
  Eigen::MatrixXd A(2, a.size()), B(2, b.size());
  for (size_t i = 0; i < a.size(); i++)
  {
    A.col(i) = a[i];
    B.col(i) = b[i];
  }
  // Umeyama's closed form (SVD of the cross-covariance, det-corrected), without scale.
  const Eigen::Matrix3d T = Eigen::umeyama(A, B, false);
  return {T(0, 2), T(1, 2), std::atan2(T(1, 0), T(0, 0))};
}

double alignmentCost(const mrpt::poses::CPose2D& T, const std::vector<Eigen::Vector2d>& a,
                     const std::vector<Eigen::Vector2d>& b)
{
  double cost = 0;
  for (size_t i = 0; i < a.size(); i++)
  {
    double x, y;
    T.composePoint(a[i].x(), a[i].y(), x, y);
    cost += (b[i] - Eigen::Vector2d(x, y)).squaredNorm();
  }
  return cost;
}

}  // namespace swslam::eval

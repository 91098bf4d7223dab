#include <swslam/geometry/information.h>

#include <gtest/gtest.h>

using swslam::geometry::informationFromCovariance;

TEST(Information, InformationIsTheInverseCovarianceWithAFloor)
{
  Eigen::Matrix3d cov;
  cov << 0.04, 0.01, 0, 0.01, 0.09, 0.002, 0, 0.002, 0.01;
  EXPECT_LT((informationFromCovariance(cov) * cov - Eigen::Matrix3d::Identity()).norm(), 1e-9);
  const Eigen::Matrix3d singular = Eigen::Vector3d(1, 0, 1).asDiagonal();
  const Eigen::Matrix3d info = informationFromCovariance(singular, 1e-6);
  EXPECT_TRUE(info.allFinite());
  EXPECT_NEAR(info(1, 1), 1e6, 1);
}

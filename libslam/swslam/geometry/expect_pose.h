#pragma once
// For tests (header only, needs GoogleTest): two planar poses equal within a tolerance, the
// headings compared modulo 2 pi.

#include <gtest/gtest.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>

namespace swslam::geometry
{
inline void expectPose(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b, double tol, const char* what)
{
  EXPECT_NEAR(a.x(), b.x(), tol) << what;
  EXPECT_NEAR(a.y(), b.y(), tol) << what;
  EXPECT_NEAR(std::remainder(a.phi() - b.phi(), 2 * M_PI), 0, tol) << what;
}

}  // namespace swslam::geometry

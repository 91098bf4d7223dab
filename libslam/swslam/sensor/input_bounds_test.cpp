#include <swslam/sensor/input_bounds.h>

#include <gtest/gtest.h>
#include <mrpt/math/CMatrixFixed.h>

#include <limits>

using swslam::sensor::kMaxMountingDistance;
using swslam::sensor::kMaxScanRays;
using swslam::sensor::mountingProblem;
using swslam::sensor::rayCountProblem;

TEST(InputBounds, AMountingWithinTheBoundIsOne)
{
  EXPECT_EQ(mountingProblem(mrpt::poses::CPose3D()), "");
  EXPECT_EQ(mountingProblem(mrpt::poses::CPose3D(0.3, -0.1, 0.4, M_PI, 0, 0)), "");
  // On the bound, in any direction.
  EXPECT_EQ(mountingProblem(mrpt::poses::CPose3D(0, -kMaxMountingDistance, 0, 0, 0, 0)), "");
  EXPECT_EQ(mountingProblem(mrpt::poses::CPose3D(30, 40, 0, 0, 0, 0)), "");
}

TEST(InputBounds, AMountingBeyondTheBoundIsNamedWithItsDistance)
{
  for (const auto& [x, y, z] : {std::tuple{1e30, 0.0, 0.0}, {1e4, 0.0, 0.0}, {0.0, 0.0, -51.0}, {36.0, 36.0, 0.0}})
  {
    const std::string p = mountingProblem(mrpt::poses::CPose3D(x, y, z, 0, 0, 0));
    EXPECT_NE(p.find("sensor mounted at"), std::string::npos) << p;
    EXPECT_NE(p.find("beyond the 50 m"), std::string::npos) << p;
  }
  EXPECT_NE(mountingProblem(mrpt::poses::CPose3D(1e30, 0, 0, 0, 0, 0)).find("1e+30 m from the vehicle"),
            std::string::npos);
}

TEST(InputBounds, AMountingThatIsNotFiniteIsNamed)
{
  for (int entry : {3, 0})  // x, then the rotation's first entry
  {
    auto m = mrpt::poses::CPose3D().getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>();
    m(0, entry) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(mountingProblem(mrpt::poses::CPose3D(m)).find("is not finite"), std::string::npos) << entry;
  }
}

TEST(InputBounds, RayCountsAboveTwoToTheTwentyAreRefused)
{
  EXPECT_EQ(rayCountProblem(0), "");
  EXPECT_EQ(rayCountProblem(kMaxScanRays), "");
  EXPECT_EQ(rayCountProblem(10000000), "a scan of 10000000 rays (more than 1048576: a corrupt count)");
  EXPECT_NE(rayCountProblem(uint64_t(1) << 40), "");
}

// Carrying an edge through merged nodes (node_merge.h): the mean is the exact composition, and
// the covariance composed with the attachments' is right (the carried edge's chi-square at the
// true anchors averages 3 over noise draws, which a wrong frame or a missing term would not).
#include <swslam/graph/node_merge.h>

#include <swslam/geometry/se2_error.h>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include <random>

using namespace swslam::graph;
using swslam::geometry::Pose2;
using mrpt::poses::CPose2D;
using mrpt::poses::CPosePDFGaussianInf;

namespace
{
Pose2 asPose2(const CPose2D& p) { return Pose2(p.x(), p.y(), p.phi()); }
CPose2D asCPose(const Pose2& p) { return CPose2D(p.x(), p.y(), p.z()); }

/** A measurement of the pose of `b` seen from `a`, its error (se2_error.h) drawn with the
 * information's covariance: z = true (+) n^-1, so that z^-1 (+) true = n. */
CPosePDFGaussianInf measure(const Pose2& a, const Pose2& b, const Eigen::Matrix3d& info, std::mt19937& rng)
{
  std::normal_distribution<double> g;
  const Eigen::Matrix3d L = info.inverse().llt().matrixL();
  const Eigen::Vector3d n = L * Eigen::Vector3d(g(rng), g(rng), g(rng));
  const CPose2D truth = asCPose(swslam::geometry::relativePose(a, b));
  return CPosePDFGaussianInf(truth + (CPose2D() - asCPose(n)), mrpt::math::CMatrixDouble33(info));
}

double chi2(const Pose2& a, const Pose2& b, const CPosePDFGaussianInf& z)
{
  const Eigen::Vector3d e = swslam::geometry::se2Error(a, b, asPose2(z.mean));
  return e.dot(z.cov_inv.asEigen() * e);
}

Eigen::Matrix3d information(double sxy, double sth, double cross = 0)
{
  Eigen::Matrix3d cov;
  cov << sxy * sxy, cross, 0, cross, 2 * sxy * sxy, 0, 0, 0, sth * sth;
  return cov.inverse();
}

struct Scene
{
  Pose2 anchor_i{2, -1, 0.4}, node_i{2.6, -0.4, 1.3};   // node i merged into anchor_i
  Pose2 node_j{9, 3, -2.2}, anchor_j{8.5, 3.4, 2.9};    // node j merged into anchor_j
};
}  // namespace

TEST(NodeMerge, ANoiseFreeEdgeCarriedToTheAnchorsIsExact)
{
  const Scene s;
  const Eigen::Matrix3d info = information(0.01, 0.01);
  auto exact = [&](const Pose2& a, const Pose2& b) {
    return CPosePDFGaussianInf(asCPose(swslam::geometry::relativePose(a, b)), mrpt::math::CMatrixDouble33(info));
  };
  const auto ai = exact(s.anchor_i, s.node_i), z = exact(s.node_i, s.node_j), aj = exact(s.anchor_j, s.node_j);
  EXPECT_LT(chi2(s.anchor_i, s.anchor_j, carryEdge(&ai, z, &aj)), 1e-16);
  EXPECT_LT(chi2(s.anchor_i, s.node_j, carryEdge(&ai, z, nullptr)), 1e-16);
  EXPECT_LT(chi2(s.node_i, s.anchor_j, carryEdge(nullptr, z, &aj)), 1e-16);
  // Carried through nothing, an edge is itself; through attachments, it is weaker.
  const auto same = carryEdge(nullptr, z, nullptr);
  EXPECT_NEAR(same.mean.x(), z.mean.x(), 1e-12);
  EXPECT_NEAR(same.mean.phi(), z.mean.phi(), 1e-12);
  EXPECT_LT((same.cov_inv.asEigen() - info).norm() / info.norm(), 1e-9);
  EXPECT_LT(carryEdge(&ai, z, &aj).cov_inv.asEigen().trace(), info.trace());
}

TEST(NodeMerge, ACarriedEdgeHasChiSquareThreeAtTheTrueAnchors)
{
  // Small noise (the composition is linearized), but anisotropic and correlated so that a
  // covariance taken in the wrong frame shows.
  const Scene s;
  const Eigen::Matrix3d attach = information(0.02, 0.01, 0.0002), edge = information(0.03, 0.015, -0.0003);
  std::mt19937 rng(5);
  const int draws = 4000;
  double both = 0, from_only = 0, to_only = 0;
  for (int d = 0; d < draws; ++d)
  {
    const auto ai = measure(s.anchor_i, s.node_i, attach, rng);
    const auto z = measure(s.node_i, s.node_j, edge, rng);
    const auto aj = measure(s.anchor_j, s.node_j, attach, rng);
    both += chi2(s.anchor_i, s.anchor_j, carryEdge(&ai, z, &aj));
    from_only += chi2(s.anchor_i, s.node_j, carryEdge(&ai, z, nullptr));
    to_only += chi2(s.node_i, s.anchor_j, carryEdge(nullptr, z, &aj));
  }
  EXPECT_NEAR(both / draws, 3.0, 0.2);
  EXPECT_NEAR(from_only / draws, 3.0, 0.2);
  EXPECT_NEAR(to_only / draws, 3.0, 0.2);
}

TEST(NodeMerge, AgreeingMeasurementsFuseIntoTheirWeightedMeanAndOthersDoNot)
{
  const Eigen::Matrix3d info = information(0.05, 0.02);
  const CPosePDFGaussianInf a(CPose2D(3, 1, 0.5), mrpt::math::CMatrixDouble33(info));
  const CPosePDFGaussianInf b(a.mean + CPose2D(0.04, -0.02, 0.01), mrpt::math::CMatrixDouble33(info));
  const auto fused = fuseAgreeing(a, b, kFuseGate);
  ASSERT_TRUE(fused.has_value());
  // Equal information: halfway, the same information (no more certain than either).
  const CPose2D mid = a.mean + CPose2D(0.02, -0.01, 0.005);
  EXPECT_NEAR(fused->mean.x(), mid.x(), 1e-4);
  EXPECT_NEAR(fused->mean.y(), mid.y(), 1e-4);
  EXPECT_NEAR(fused->mean.phi(), mid.phi(), 1e-6);
  EXPECT_NEAR(fused->cov_inv(0, 0), info(0, 0), 1e-4 * info(0, 0));  // b turned by 0.01 rad
  const CPosePDFGaussianInf far(a.mean + CPose2D(0.5, 0, 0), mrpt::math::CMatrixDouble33(info));
  EXPECT_FALSE(fuseAgreeing(a, far, kFuseGate).has_value());
}

TEST(NodeMerge, AFusedMeasurementIsConsistentWhateverTheCorrelation)
{
  // Two noisy measurements of one relative pose, of different information: independent, the
  // fused one is conservative (chi-square below 3 on average); with one error shared by both
  // (the same scans matched on two laps), it is still no more certain than it is, where the
  // information-weighted mean would claim twice the certainty (chi-square near 6).
  const Pose2 from(1, 2, 0.3), to(4, 0, 2.0);
  const Eigen::Matrix3d ia = information(0.03, 0.01, 0.0002), ib = information(0.03, 0.012, -0.0001);
  std::mt19937 rng(9);
  const int draws = 4000;
  double independent = 0, shared = 0;
  for (int d = 0; d < draws; ++d)
  {
    const auto f = fuseAgreeing(measure(from, to, ia, rng), measure(from, to, ib, rng), 1e9);
    ASSERT_TRUE(f.has_value());
    independent += chi2(from, to, *f);
    const auto a = measure(from, to, ia, rng);
    const CPosePDFGaussianInf b(a.mean, mrpt::math::CMatrixDouble33(ib));
    shared += chi2(from, to, *fuseAgreeing(a, b, 1e9));
  }
  EXPECT_LT(independent / draws, 3.0);
  EXPECT_GT(independent / draws, 1.5);
  EXPECT_NEAR(shared / draws, 3.0, 0.3);
}

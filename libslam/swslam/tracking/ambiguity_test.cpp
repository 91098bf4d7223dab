// Weak directions of a match and the prior taken along them, against closed forms and a slow
// version that inverts the covariance.
#include <swslam/tracking/ambiguity.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace swslam::tracking;

namespace
{
/** The slow version: invert the covariance, normalize it, and compare every eigenvalue with the
 * largest. Returns the weakest / strongest ratio and the weak directions' count. */
std::pair<double, int> slowWeak(const Eigen::Matrix3d& cov, double length, double threshold)
{
  const Eigen::Matrix3d S = Eigen::Vector3d(1, 1, length).asDiagonal();
  const Eigen::Matrix3d info = S.inverse() * cov.inverse() * S.inverse();
  const Eigen::Vector3d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(info).eigenvalues();
  int weak = 0;
  for (int k = 0; k < 3; k++) weak += l(k) / l(2) < threshold ? 1 : 0;
  return {l(0) / l(2), weak};
}

Eigen::Matrix3d randomCovariance(std::mt19937& rng)
{
  std::normal_distribution<double> n;
  Eigen::Matrix3d A;
  for (int i = 0; i < 9; i++) A(i) = n(rng);
  const Eigen::Matrix3d Q = Eigen::HouseholderQR<Eigen::Matrix3d>(A).householderQ();
  std::uniform_real_distribution<double> logv(-5, 0);
  const Eigen::Vector3d v(std::pow(10, logv(rng)), std::pow(10, logv(rng)), std::pow(10, logv(rng)));
  return Q * v.asDiagonal() * Q.transpose();
}
}  // namespace

TEST(Ambiguity, ThresholdIsWhatNoiseFakesTimesTheFactor)
{
  // 3 cm noise on a 0.2 m segment tilts its normal by sqrt(2) 0.03 / 0.2 rad: 0.045 of a
  // point's information goes to the direction across it.
  EXPECT_NEAR(weakRatioThreshold(0.03 * 0.03, 0.2, 1), 0.045, 1e-12);
  EXPECT_NEAR(weakRatioThreshold(2 * 0.03 * 0.03, 0.2, 2), 0.18, 1e-12);
  EXPECT_EQ(weakRatioThreshold(1.0, 0.2, 1), 0.5) << "clamped";
  EXPECT_EQ(weakRatioThreshold(0.03 * 0.03, 0, 1), 0) << "no segment length: nothing to derive";
  EXPECT_EQ(weakRatioThreshold(0.03 * 0.03, 0.2, 0), 0) << "off";
  EXPECT_EQ(weakRatioThreshold(0, 0.2, 1), 0) << "no noise";
  EXPECT_EQ(weakRatioThreshold(std::nan(""), 0.2, 1), 0);
  // 23 residuals of 2 cm rms less three fitted parameters.
  EXPECT_NEAR(residualNoiseVariance(20 * 0.02 * 0.02, 23, 1.0), 0.02 * 0.02, 1e-15);
  EXPECT_EQ(residualNoiseVariance(5.0, 3, 0.5), 0.5) << "no degree of freedom";
  EXPECT_EQ(residualNoiseVariance(0.0, 0, 0.5), 0.5);
}

TEST(Ambiguity, AgreesWithTheInverseOfTheCovariance)
{
  std::mt19937 rng(3);
  for (int trial = 0; trial < 500; trial++)
  {
    const Eigen::Matrix3d cov = randomCovariance(rng);
    const double length = 0.5 + trial % 7;
    const Ambiguity a = findWeakDirections(cov, length, 0.01);
    const auto [ratio, weak] = slowWeak(cov, length, 0.01);
    ASSERT_NEAR(std::log(a.ratio), std::log(ratio), 1e-4) << "trial " << trial;
    // An eigenvalue within round-off of the threshold may go either way.
    if (std::abs(std::log(ratio / 0.01)) > 1e-4) ASSERT_EQ(a.weak, weak) << "trial " << trial;
    // The weak directions are unit eigenvectors of the normalized information.
    const Eigen::Matrix3d S = Eigen::Vector3d(1, 1, length).asDiagonal();
    const Eigen::Matrix3d info = S.inverse() * cov.inverse() * S.inverse();
    for (int k = 0; k < a.weak; k++)
    {
      const Eigen::Vector3d v = a.directions.col(k);
      ASSERT_NEAR(v.norm(), 1, 1e-9);
      const Eigen::Vector3d iv = info * v;
      ASSERT_LT((iv - v.dot(iv) * v).norm(), 1e-6 * info.norm()) << "trial " << trial;
    }
  }
}

TEST(Ambiguity, ACorridorsAxisIsWeakAndOnlyIt)
{
  // Along x the variance is 100 times the cross-axis one: information ratio 0.01.
  const Eigen::Matrix3d cov = Eigen::Vector3d(1e-2, 1e-4, 1e-5).asDiagonal();
  const Ambiguity a = findWeakDirections(cov, 3.0, 0.09);
  ASSERT_EQ(a.weak, 1);
  EXPECT_NEAR(std::abs(a.directions(0, 0)), 1, 1e-12);
  EXPECT_EQ(findWeakDirections(cov, 3.0, 0.005).weak, 0) << "below the threshold's own ratio";
}

TEST(Ambiguity, ABadCovarianceHasEveryDirectionWeak)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(findWeakDirections(Eigen::Matrix3d::Constant(nan), 1, 0.1).weak, 3);
  EXPECT_EQ(findWeakDirections(Eigen::Matrix3d::Zero(), 1, 0.1).weak, 3);
  EXPECT_EQ(findWeakDirections(-Eigen::Matrix3d::Identity(), 1, 0.1).weak, 3);
  EXPECT_EQ(findWeakDirections(Eigen::Matrix3d::Identity(), 0, 0.1).weak, 3);
}

TEST(Ambiguity, ThePriorDecidesAlongTheWeakDirectionOnly)
{
  // A wall along x: x is weak. The prior's x replaces the match's, y and theta stay.
  const Eigen::Matrix3d cov0 = Eigen::Vector3d(1e6, 1e-4, 1e-5).asDiagonal();
  const Ambiguity a = findWeakDirections(cov0, 4.0, 0.09);
  ASSERT_EQ(a.weak, 1);
  Eigen::Vector3d pose(2.0, 0.3, 0.1);
  Eigen::Matrix3d cov = cov0;
  const Eigen::Matrix3d prior_cov = Eigen::Vector3d(1.0, 1.0, 0.03).asDiagonal();
  takePriorAlongWeak(pose, cov, Eigen::Vector3d(0.5, 0.0, 2 * M_PI + 0.05), prior_cov, a, 4.0);
  EXPECT_NEAR(pose.x(), 0.5, 1e-12);
  EXPECT_NEAR(pose.y(), 0.3, 1e-9);
  EXPECT_NEAR(pose.z(), 0.1, 1e-9);
  EXPECT_NEAR(cov(0, 0), 1.0, 1e-6) << "the prior's variance along the axis";
  EXPECT_NEAR(cov(1, 1), 1e-4, 1e-12);
  EXPECT_NEAR(cov(2, 2), 1e-5, 1e-12);

  // A weak direction mixing x and theta (normalized u = [x, y, L theta]): the pose moves by
  // the prior's difference projected on it, in those units.
  Ambiguity m;
  m.weak = 1;
  m.directions.col(0) = Eigen::Vector3d(1, 0, 1).normalized();
  Eigen::Vector3d p(0, 0, 0);
  Eigen::Matrix3d c = Eigen::Matrix3d::Identity() * 1e-4;
  takePriorAlongWeak(p, c, Eigen::Vector3d(1.0, 5.0, 0.0), Eigen::Matrix3d::Zero(), m, 2.0);
  // An exact prior: d = [1, 5, 0] -> u = [1, 5, 0]; along v: 1 / sqrt(2) -> shift u
  // [0.5, 0, 0.5] -> theta 0.25.
  EXPECT_NEAR(p.x(), 0.5, 1e-12);
  EXPECT_NEAR(p.y(), 0.0, 1e-12);
  EXPECT_NEAR(p.z(), 0.25, 1e-12);

  // No weak direction: nothing changes.
  Eigen::Vector3d q(1, 2, 3);
  Eigen::Matrix3d cq = Eigen::Matrix3d::Identity();
  takePriorAlongWeak(q, cq, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), Ambiguity(), 1);
  EXPECT_EQ(q, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(cq, Eigen::Matrix3d::Identity());
}

TEST(Ambiguity, AWeakDirectionTakesThePriorsValueAndVariance)
{
  // y is weak: the match's y (variance 0.04) gives way to the prior's (variance 0.01).
  Ambiguity a;
  a.weak = 1;
  a.directions.col(0) = Eigen::Vector3d(0, 1, 0);
  Eigen::Vector3d pose(1, 2, 0.3);
  Eigen::Matrix3d cov = Eigen::Vector3d(1e-4, 0.04, 1e-5).asDiagonal();
  const Eigen::Vector3d prior(5, 1, -0.2);
  const Eigen::Matrix3d prior_cov = Eigen::Vector3d(0.01, 0.01, 0.01).asDiagonal();
  takePriorAlongWeak(pose, cov, prior, prior_cov, a, 3.0);
  EXPECT_NEAR(pose.y(), 1, 1e-12);
  EXPECT_NEAR(cov(1, 1), 0.01, 1e-12);
  EXPECT_EQ(pose.x(), 1);
  EXPECT_EQ(pose.z(), 0.3);
  EXPECT_EQ(cov(0, 0), 1e-4);
  EXPECT_EQ(cov(2, 2), 1e-5);
  // A covariance that is not finite: the prior alone.
  Eigen::Matrix3d bad = Eigen::Matrix3d::Constant(std::nan(""));
  Eigen::Vector3d p2(1, 2, 3);
  takePriorAlongWeak(p2, bad, prior, prior_cov, findWeakDirections(bad, 1, 0.1), 1.0);
  EXPECT_EQ(p2, prior);
  EXPECT_EQ(bad, prior_cov);
}

namespace
{
/** Points along the segment a-b, `n` of them, in order. */
void addLine(std::vector<Eigen::Vector2d>& pts, Eigen::Vector2d a, Eigen::Vector2d b, int n)
{
  for (int k = 0; k < n; k++) pts.push_back(a + (b - a) * k / (n - 1.0));
}

/** The slow version of raysFacing: each point and normal turned into the directions' frame
 * explicitly, the point-to-line residual's change per unit step along v by finite differences
 * of the pose [x, y, theta] = v / diag(1, 1, length) * h. */
size_t slowFacing(const std::vector<Eigen::Vector2d>& pts, const FacingNormals& nrm, double heading,
                  const Eigen::Vector3d& v, double length)
{
  const Eigen::Rotation2Dd R(heading);
  const double h = 1e-6;
  size_t count = 0;
  for (size_t i = 0; i < pts.size(); i++)
  {
    bool facing = false;
    for (const Eigen::Vector2d& n0 : {nrm.lo[i], nrm.hi[i]})
    {
      const Eigen::Vector2d q = R * pts[i], n = R * n0;
      // Moving the scan by the pose moves q to Rot(theta) q + t; the residual is n . (that - q).
      const Eigen::Vector3d d = h * Eigen::Vector3d(v.x(), v.y(), v.z() / length);
      const Eigen::Vector2d moved = Eigen::Rotation2Dd(d.z()) * q + d.head<2>();
      if (std::abs(n.dot(moved - q)) / h >= kFacingSensitivity) facing = true;
    }
    count += facing;
  }
  return count;
}
}  // namespace

TEST(Ambiguity, FacingNormalsAreThoseOfTheSurfaceNotOfAGap)
{
  // A wall along x at y = 2, a gap, then a wall along y at x = 3 (a corner seen from afar).
  std::vector<Eigen::Vector2d> pts;
  addLine(pts, {-2, 2}, {1, 2}, 61);  // 5 cm apart
  addLine(pts, {3, 1.5}, {3, -1.5}, 31);  // 10 cm apart, 2 m from the first wall's end
  const FacingNormals n = facingNormals(pts, 0.2);
  for (size_t i = 0; i < pts.size(); i++)
    for (const Eigen::Vector2d& v : {n.lo[i], n.hi[i]})
      if (v.squaredNorm() > 0)
      {
        EXPECT_NEAR(v.norm(), 1.0, 1e-12);
        EXPECT_NEAR(std::abs(v.dot(i < 61 ? Eigen::Vector2d(0, 1) : Eigen::Vector2d(1, 0))), 1.0, 1e-9) << i;
      }
  // No chord spans the gap: the first wall's last points have no normal on the high side, the
  // second wall's first points none on the low side; inside each wall both exist.
  EXPECT_EQ(n.hi[60].squaredNorm(), 0);
  EXPECT_EQ(n.lo[61].squaredNorm(), 0);
  EXPECT_GT(n.lo[30].squaredNorm(), 0);
  EXPECT_GT(n.hi[30].squaredNorm(), 0);
  // A point with no neighbour 20 cm away on a side has no normal there (the scan's ends).
  EXPECT_EQ(n.lo[0].squaredNorm(), 0);
  EXPECT_EQ(n.hi[90].squaredNorm(), 0);
}

TEST(Ambiguity, RaysFacingADirectionAgreeWithTheSlowVersion)
{
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 0.01);
  std::vector<Eigen::Vector2d> pts;
  addLine(pts, {-4, 1.5}, {4, 1.5}, 161);
  addLine(pts, {4.5, 1.0}, {4.5, -1.0}, 21);  // an end wall
  addLine(pts, {3, -1.5}, {-4, -1.5}, 141);
  for (auto& p : pts) p += Eigen::Vector2d(noise(rng), noise(rng));
  const FacingNormals n = facingNormals(pts, 0.2);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int t = 0; t < 200; t++)
  {
    const Eigen::Vector3d v = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const double heading = 3 * u(rng), length = 1 + std::abs(2 * u(rng));
    EXPECT_EQ(raysFacing({pts, n, heading}, v, length), slowFacing(pts, n, heading, v, length));
  }
  // Along the corridor's axis only the end wall faces; across it, both side walls.
  EXPECT_NEAR(static_cast<double>(raysFacing({pts, n, 0.0}, {1, 0, 0}, 3.0)), 21, 2);
  EXPECT_GT(raysFacing({pts, n, 0.0}, {0, 1, 0}, 3.0), 250u);
}

TEST(Ambiguity, AWallsLineIsUnobservableACorridorWithAnEndIsNot)
{
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 0.01);
  std::vector<Eigen::Vector2d> wall, ended;
  addLine(wall, {-4, 1.5}, {4, 1.5}, 161);
  ended = wall;
  addLine(ended, {4.5, 1.0}, {4.5, -1.0}, 21);
  for (auto* s : {&wall, &ended})
    for (auto& p : *s) p += Eigen::Vector2d(noise(rng), noise(rng));
  const FacingNormals nw = facingNormals(wall, 0.2), ne = facingNormals(ended, 0.2);
  Ambiguity a;
  a.weak = 1;
  a.directions.col(0) = Eigen::Vector3d(1, 0, 0);
  // Both scans see only the wall: unobservable (noise tilts no 20 cm chord by 0.3).
  EXPECT_EQ(unobservableDirections(a, {wall, nw, 0.0}, {wall, nw, 0.0}, 3.0, 3).weak, 1);
  // One of them sees the end wall: the other does not, so their overlap does not either.
  EXPECT_EQ(unobservableDirections(a, {ended, ne, 0.0}, {wall, nw, 0.0}, 3.0, 3).weak, 1);
  // Both see it: observable, if weakly.
  EXPECT_EQ(unobservableDirections(a, {ended, ne, 0.0}, {ended, ne, 0.0}, 3.0, 3).weak, 0);
  // Off (0), or no weak direction to test: none.
  EXPECT_EQ(unobservableDirections(a, {wall, nw, 0.0}, {wall, nw, 0.0}, 3.0, 0).weak, 0);
  a.weak = 0;
  EXPECT_EQ(unobservableDirections(a, {wall, nw, 0.0}, {wall, nw, 0.0}, 3.0, 3).weak, 0);
  // Mismatched sizes count nothing (and read nothing past the scan).
  const FacingNormals empty;
  EXPECT_EQ(raysFacing({wall, empty, 0.0}, {0, 1, 0}, 3.0), 0u);
}

TEST(Ambiguity, RaysFacingStopsCountingAtEnough)
{
  std::vector<Eigen::Vector2d> pts;
  addLine(pts, {-4, 1.5}, {4, 1.5}, 161);
  const FacingNormals n = facingNormals(pts, 0.2);
  const size_t all = raysFacing({pts, n, 0.0}, {0, 1, 0}, 3.0);
  ASSERT_GT(all, 100u);
  EXPECT_EQ(raysFacing({pts, n, 0.0}, {0, 1, 0}, 3.0, 3), 3u);
  EXPECT_EQ(raysFacing({pts, n, 0.0}, {0, 1, 0}, 3.0, all + 5), all);
}

// Truncated least squares (truncated.h): the GNC surrogate's weights against the paper's
// limits, the truncated cost against a direct sum, and graduated TLS on a robust mean against
// the exhaustive TLS optimum.
#include <swslam/graph/truncated.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace swslam::graph;

TEST(Truncated, TheWeightIsOneInsideZeroOutsideAndContinuousBetween)
{
  const double c2 = 16;
  for (const double mu : {0.01, 0.3, 1.0, 10.0, 1000.0})
  {
    const double lo = c2 * mu / (mu + 1), hi = c2 * (mu + 1) / mu;
    EXPECT_EQ(gncTlsWeight(0.5 * lo, c2, mu), 1.0);
    EXPECT_EQ(gncTlsWeight(2 * hi, c2, mu), 0.0);
    EXPECT_NEAR(gncTlsWeight(lo * (1 + 1e-9), c2, mu), 1.0, 1e-6);
    EXPECT_NEAR(gncTlsWeight(hi * (1 - 1e-9), c2, mu), 0.0, 1e-6);
    // Decreasing between the two.
    double last = 1.0;
    for (double r2 = lo; r2 <= hi; r2 += (hi - lo) / 50)
    {
      const double w = gncTlsWeight(r2, c2, mu);
      EXPECT_LE(w, last + 1e-12);
      last = w;
    }
  }
  // mu -> infinity: the TLS weight itself, 1 within the gate and 0 beyond.
  EXPECT_EQ(gncTlsWeight(15.9, c2, 1e9), 1.0);
  EXPECT_EQ(gncTlsWeight(16.1, c2, 1e9), 0.0);
}

TEST(Truncated, TheCostIsTheChi2UpToEachKindsGate)
{
  GraphProblem p;
  p.poses = {swslam::geometry::Pose2::Zero(), swslam::geometry::Pose2(1, 0, 0)};
  p.fixed = {1, 0};
  auto edge = [](double x, bool robust, EdgeKind kind) {
    GraphProblem::Edge e;
    e.i = 0, e.j = 1, e.z = swslam::geometry::Pose2(x, 0, 0), e.robust = robust, e.kind = kind;
    return e;
  };
  // Residuals 0.5 (chi2 0.25), 3 (9), 10 (100) and, not robustified, 10 (100).
  p.edges = {edge(1.5, true, EdgeKind::Loop), edge(4, true, EdgeKind::Loop), edge(11, true, EdgeKind::Loop),
             edge(11, false, EdgeKind::Consecutive), edge(11, true, EdgeKind::Consecutive)};
  const OutlierGates gates{4.0, 6.0};
  EXPECT_NEAR(truncatedCost(p, gates), 0.25 + 9 + 16 + 100 + 36, 1e-9);
}

TEST(Truncated, GraduatedTlsFindsTheMeanOfTheInliers)
{
  // A robust mean: x minimizes sum w_k (x - y_k)^2; 30 inliers near 5 (sd 1), 25 outliers
  // spread over [-100, 100] (a share no median survives).
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0, 1);
  std::uniform_real_distribution<double> far(-100, 100);
  std::vector<double> y;
  for (int k = 0; k < 30; ++k) y.push_back(5 + noise(rng));
  for (int k = 0; k < 25; ++k)
  {
    double v = far(rng);
    while (std::abs(v - 5) < 10) v = far(rng);
    y.push_back(v);
  }
  const std::vector<char> robust(y.size(), 1);
  const std::vector<double> c2(y.size(), 9.0);
  double x = 0;
  const std::vector<double> w = graduatedTls(
      robust, c2, 0,
      [&](const std::vector<double>& wk) {
        double s = 0, sw = 0;
        for (size_t k = 0; k < y.size(); ++k) s += wk[k] * y[k], sw += wk[k];
        x = sw > 0 ? s / sw : x;
      },
      [&](size_t k) { return (x - y[k]) * (x - y[k]); });
  // The exhaustive TLS optimum over a fine grid of x.
  double best = 0, best_cost = std::numeric_limits<double>::infinity();
  for (double t = -100; t <= 100; t += 1e-3)
  {
    double c = 0;
    for (const double v : y) c += std::min((t - v) * (t - v), 9.0);
    if (c < best_cost) best_cost = c, best = t;
  }
  EXPECT_NEAR(x, best, 0.05);
  for (size_t k = 0; k < y.size(); ++k)
  {
    EXPECT_TRUE(w[k] == 0.0 || w[k] == 1.0);
    EXPECT_EQ(w[k] == 1.0, k < 30) << "sample " << k << " at " << y[k];
  }
}

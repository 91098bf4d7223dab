#include <swslam/eval/relations.h>
#include <swslam/eval/relations_io.h>

#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "eval_test_support.h"
#include "test_support.h"

using swslam::eval::Relation;
using swslam::test::homogeneous;

namespace
{
/** Relations between pose i and pose i + gap of `truth`, as the Freiburg files hold. */
std::vector<Relation> relationsFrom(const std::vector<swslam::common::StampedPose>& truth, size_t gap)
{
  std::vector<Relation> out;
  for (size_t i = 0; i + gap < truth.size(); i += 3)
    out.push_back({truth[i].t, truth[i + gap].t, truth[i + gap].pose - truth[i].pose, true});
  return out;
}
}  // namespace

TEST(EvalRelations, FileRoundTripAndFreiburgLines)
{
  const auto dir = swslam::test::tempDir("relations");
  std::ofstream(dir + "/a.relations")
      << "# timestamp1 timestamp2 x y z roll pitch yaw\n"
      << "1232658478.161285 1232658644.149293 1.031273 -0.003531 0.000000 0.000000 -0.000000 "
         "-0.009755\n"
      << "\n1.0 2.0 0.5 0.25 0.3 0 0 0.1\n";
  const auto r = swslam::eval::readRelations(dir + "/a.relations");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_DOUBLE_EQ(r[0].t1, 1232658478.161285);
  EXPECT_DOUBLE_EQ(r[0].t2, 1232658644.149293);
  EXPECT_DOUBLE_EQ(r[0].delta.x(), 1.031273);
  EXPECT_NEAR(r[0].delta.phi(), -0.009755, 1e-15);
  EXPECT_TRUE(r[0].planar);
  EXPECT_FALSE(r[1].planar);  // z = 0.3

  std::ofstream(dir + "/b.relations") << swslam::eval::formatRelations(r);
  const auto back = swslam::eval::readRelations(dir + "/b.relations");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_NEAR(back[1].delta.y(), 0.25, 1e-12);
  EXPECT_NEAR(back[0].t1, r[0].t1, 1e-6);
}

TEST(EvalRelations, AnyFiniteTimeWritesALineThatReadsBack)
{
  // Two "%.6f" times of 1e308 s: a fixed buffer cut the line (found by fuzzing,
  // tests/fuzz/regressions/relations_io).
  const auto dir = swslam::test::tempDir("relations_long");
  const std::vector<Relation> r = {{1e308, -1e308, {1, 2, 0.5}, true}};
  std::ofstream(dir + "/long.relations") << swslam::eval::formatRelations(r);
  const auto back = swslam::eval::readRelations(dir + "/long.relations");
  ASSERT_EQ(back.size(), 1u);
  EXPECT_DOUBLE_EQ(back[0].t1, 1e308);
  EXPECT_DOUBLE_EQ(back[0].t2, -1e308);
  EXPECT_NEAR(back[0].delta.phi(), 0.5, 1e-9);
}

TEST(EvalRelations, MalformedLineIsNamed)
{
  const auto dir = swslam::test::tempDir("relations_bad");
  for (const char* bad : {"1 2 3 4 5 6 7\n", "1 2 3 4 5 6 7 8 9\n", "1 2 x 4 5 6 7 8\n",
                          "1 2 3 4 5 6 7 nan\n"})
  {
    std::ofstream(dir + "/r.relations") << "# header\n0 1 0 0 0 0 0 0\n" << bad;
    try
    {
      swslam::eval::readRelations(dir + "/r.relations");
      FAIL() << bad;
    }
    catch (const std::runtime_error& e)
    {
      EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(swslam::eval::readRelations(dir + "/missing.relations"), std::runtime_error);
}

TEST(EvalRelations, RelationsFromTheTruthGiveZeroError)
{
  const auto truth = swslam::test::wanderingPath(200, 100, 21);
  const auto r = swslam::eval::relationsError(
      swslam::test::transformed(truth, {5, 5, 1.0}), relationsFrom(truth, 7), 0.01);
  EXPECT_GT(r.used, 50u);
  EXPECT_EQ(r.unmatched, 0u);
  EXPECT_NEAR(r.translation.max, 0, 1e-9);
  EXPECT_NEAR(r.rotation.max, 0, 1e-9);
  EXPECT_NEAR(r.translation_sq.mean, 0, 1e-18);
}

TEST(EvalRelations, NoisyEstimateEqualsTheMatrixFormula)
{
  std::mt19937 rng(4);
  std::normal_distribution<double> n(0, 0.03);
  const auto truth = swslam::test::wanderingPath(150, 0, 5);
  auto est = truth;
  for (auto& p : est)
  {
    p.pose = {p.pose.x() + n(rng), p.pose.y() + n(rng), p.pose.phi() + n(rng)};
    p.t += 0.004;  // within the tolerance
  }
  auto rel = relationsFrom(truth, 10);
  rel.push_back({999, 1000, {}, true});  // no estimate there
  std::vector<double> t, a;
  for (size_t k = 0; k + 1 < rel.size(); k++)
  {
    const size_t i = std::lround(rel[k].t1 / 0.1), j = std::lround(rel[k].t2 / 0.1);
    // delta*^-1 (x_i^-1 x_j)
    const Eigen::Matrix3d E = homogeneous(rel[k].delta).inverse() *
                              homogeneous(est[i].pose).inverse() * homogeneous(est[j].pose);
    t.push_back(swslam::test::transNorm(E));
    a.push_back(swslam::test::rotAngle(E));
  }
  const auto r = swslam::eval::relationsError(est, rel, 0.01);
  EXPECT_EQ(r.used, rel.size() - 1);
  EXPECT_EQ(r.unmatched, 1u);
  double mt = 0, ma = 0, mt2 = 0, ma2 = 0;
  for (size_t k = 0; k < t.size(); k++)
  {
    mt += t[k] / t.size();
    ma += a[k] / t.size();
    mt2 += t[k] * t[k] / t.size();
    ma2 += a[k] * a[k] / t.size();
  }
  EXPECT_NEAR(r.translation.mean, mt, 1e-12);
  EXPECT_NEAR(r.rotation.mean, ma, 1e-12);
  EXPECT_NEAR(r.translation_sq.mean, mt2, 1e-12);
  EXPECT_NEAR(r.rotation_sq.mean, ma2, 1e-12);
  EXPECT_GT(r.translation.stddev, 0);

  // A stamp outside the tolerance is unmatched.
  EXPECT_EQ(swslam::eval::relationsError(est, rel, 0.001).used, 0u);
}

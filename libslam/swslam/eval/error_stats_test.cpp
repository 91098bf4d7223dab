#include <swslam/eval/error_stats.h>

#include <gtest/gtest.h>

#include <cmath>

TEST(EvalErrorStats, KnownValues)
{
  const auto s = swslam::eval::errorStats({3, 1, 4, 1, 5, 9});
  EXPECT_EQ(s.n, 6u);
  EXPECT_DOUBLE_EQ(s.mean, 23.0 / 6);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt((9 + 1 + 16 + 1 + 25 + 81) / 6.0));
  EXPECT_DOUBLE_EQ(s.median, 3.5);
  EXPECT_DOUBLE_EQ(s.max, 9);
  double dev = 0;
  for (double x : {3, 1, 4, 1, 5, 9}) dev += (x - 23.0 / 6) * (x - 23.0 / 6);
  EXPECT_DOUBLE_EQ(s.stddev, std::sqrt(dev / 5));

  const auto odd = swslam::eval::errorStats({2, 7, 1});
  EXPECT_DOUBLE_EQ(odd.median, 2);
  const auto single = swslam::eval::errorStats({0.5});
  EXPECT_DOUBLE_EQ(single.stddev, 0);
  EXPECT_DOUBLE_EQ(single.median, 0.5);
}

TEST(EvalErrorStats, EmptyIsNaN)
{
  const auto s = swslam::eval::errorStats({});
  EXPECT_EQ(s.n, 0u);
  EXPECT_TRUE(std::isnan(s.rmse) && std::isnan(s.mean) && std::isnan(s.max));
}

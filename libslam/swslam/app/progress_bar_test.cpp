// The progress line's text: bar, percentage, rate and ETA.
#include <swslam/app/progress_bar.h>

#include <gtest/gtest.h>

#include <cmath>

using swslam::app::ProgressBar;

TEST(ProgressBar, ShowsFractionRateAndEta)
{
  const std::string s = ProgressBar::format(0.25, 500, 10.0, "12 nodes");
  EXPECT_NE(s.find("[########......................]"), std::string::npos) << s;
  EXPECT_NE(s.find(" 25%"), std::string::npos) << s;
  EXPECT_NE(s.find("500 scans 50 scans/s"), std::string::npos) << s;
  EXPECT_NE(s.find("ETA 0:30"), std::string::npos) << s;  // 10 s for 25 %: 30 s left
  EXPECT_NE(s.find("12 nodes"), std::string::npos) << s;
}

TEST(ProgressBar, UnknownEtaAndOutOfRangeFractions)
{
  EXPECT_NE(ProgressBar::format(0.0, 0, 0.0, "").find("ETA --:--"), std::string::npos);
  EXPECT_NE(ProgressBar::format(2.0, 10, 1.0, "").find("100%"), std::string::npos);
  EXPECT_NE(ProgressBar::format(std::nan(""), 10, 1.0, "").find("  0%"), std::string::npos);
}

TEST(ProgressBar, DueOnlyWhenEnabledAndNotJustDrawn)
{
  ProgressBar off(stderr, false);
  EXPECT_FALSE(off.due());
  std::FILE* sink = std::fopen("/dev/null", "w");
  ASSERT_NE(sink, nullptr);
  ProgressBar on(sink, true);
  EXPECT_TRUE(on.due());
  on.update(0.5, 10);
  EXPECT_FALSE(on.due());  // redrawn at most every 200 ms
  std::fclose(sink);
}

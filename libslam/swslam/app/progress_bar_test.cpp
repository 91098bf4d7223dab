// The progress line's text: bar, percentage, rate and ETA.
#include <swslam/app/progress_bar.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>

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

TEST(ProgressBar, OffATerminalAPlainLineAtEveryTenth)
{
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  swslam::app::ProgressBar lines(f, swslam::app::ProgressStyle::Lines, "swslam: ");
  for (int k = 1; k <= 100; k++)
  {
    // The figures are gathered at most every 200 ms (due()); a line is printed only when a new
    // tenth is reached.
    if (k % 10 == 0) std::this_thread::sleep_for(std::chrono::milliseconds(210));
    if (lines.due()) lines.update(k / 100.0, 10 * k, "3 nodes");
  }
  lines.done();
  std::rewind(f);
  std::string text;
  for (int c; (c = std::fgetc(f)) != EOF;) text += static_cast<char>(c);
  std::fclose(f);
  EXPECT_EQ(text.find('\r'), std::string::npos) << text;
  EXPECT_EQ(text.find('\033'), std::string::npos) << text;
  EXPECT_NE(text.find("swslam:  10% "), std::string::npos) << text;
  EXPECT_NE(text.find("swslam: 100% 1000 scans"), std::string::npos) << text;
  EXPECT_NE(text.find("3 nodes\n"), std::string::npos) << text;
  size_t count = 0;
  for (size_t at = text.find("swslam:"); at != std::string::npos; at = text.find("swslam:", at + 1)) count++;
  EXPECT_EQ(count, 10u) << text;  // one line per tenth, none twice
}

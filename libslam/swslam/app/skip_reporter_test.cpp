#include <gtest/gtest.h>
#include <swslam/app/skip_reporter.h>

#include <sstream>

namespace swslam::app
{
namespace
{
size_t lines(const std::string& s)
{
  size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}
}  // namespace

TEST(SkipReporter, PrintsTheFirstMessagesOfEachKindAndCountsAll)
{
  std::ostringstream err;
  SkipReporter r(err, 2, "app: ");
  for (size_t i = 0; i < 5; ++i) r.report(system::FeedStatus::TimestampNotIncreasing, i, "stamp " + std::to_string(i));
  r.report(system::FeedStatus::BadGeometry, 7, "no beams");
  EXPECT_EQ(r.count(system::FeedStatus::TimestampNotIncreasing), 5u);
  EXPECT_EQ(r.count(system::FeedStatus::BadGeometry), 1u);
  EXPECT_EQ(r.count(system::FeedStatus::OdometryDropped), 0u);
  const std::string s = err.str();
  EXPECT_NE(s.find("app: skipped input scan 0: stamp 0\n"), std::string::npos);
  EXPECT_NE(s.find("app: skipped input scan 1: stamp 1\n"), std::string::npos);
  EXPECT_EQ(s.find("stamp 2"), std::string::npos);
  EXPECT_NE(s.find("app: (further messages of this kind are only counted)\n"), std::string::npos);
  EXPECT_NE(s.find("app: skipped input scan 7: no beams\n"), std::string::npos);
  EXPECT_EQ(lines(s), 4u);  // two, the note, and the other kind's first
}

TEST(SkipReporter, ScansTakenInPartAreNotCalledSkipped)
{
  std::ostringstream err;
  SkipReporter r(err, 10, "app: ");
  r.report(system::FeedStatus::OdometryDropped, 3, "odometry not finite");
  r.report(system::FeedStatus::TimestampsResumed, 9, "the log resumes");
  EXPECT_EQ(err.str(), "app: input scan 3: odometry not finite\napp: input scan 9: the log resumes\n");
}

TEST(SkipReporter, ZeroPrintsOnlyTheNote)
{
  std::ostringstream err;
  SkipReporter r(err, 0, "app: ");
  r.report(system::FeedStatus::BadGeometry, 0, "a");
  r.report(system::FeedStatus::BadGeometry, 1, "b");
  EXPECT_EQ(err.str(), "app: (further messages of this kind are only counted)\n");
  EXPECT_EQ(r.count(system::FeedStatus::BadGeometry), 2u);
}
}  // namespace swslam::app

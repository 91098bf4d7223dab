// Keeping every Nth scan: which scans, and the odometry of the ones left out.
#include <swslam/io/throttled_scan_source.h>

#include <gtest/gtest.h>

#include <random>

using namespace swslam;
using namespace swslam::io;
using mrpt::poses::CPose2D;

namespace
{
/** Scans stamped 0, 1, 2... s with the given increments (nullopt: none). */
class ListSource : public ScanSource
{
 public:
  explicit ListSource(std::vector<std::optional<CPose2D>> increments) : increments_(std::move(increments)) {}
  bool next(sensor::ScanInput& out) override
  {
    if (k_ == increments_.size()) return false;
    out.observation = mrpt::obs::CObservation2DRangeScan::Create();
    out.observation->timestamp = mrpt::Clock::fromDouble(1000.0 + k_);
    out.odometry_increment = increments_[k_++];
    stats_.scans++;
    return true;
  }
  const ScanSourceStats& stats() const override { return stats_; }
  std::string describe() const override { return "list"; }
  double fractionRead() const override { return increments_.empty() ? 1.0 : double(k_) / increments_.size(); }

 private:
  std::vector<std::optional<CPose2D>> increments_;
  size_t k_ = 0;
  ScanSourceStats stats_;
};

double secondOf(const sensor::ScanInput& in) { return mrpt::Clock::toDouble(in.observation->timestamp) - 1000.0; }
}  // namespace

TEST(ThrottledScanSource, KeepsTheFirstScanAndThenEveryNth)
{
  ThrottledScanSource s(std::make_unique<ListSource>(std::vector<std::optional<CPose2D>>(11)), 4);
  std::vector<double> kept;
  sensor::ScanInput in;
  while (s.next(in)) kept.push_back(secondOf(in));
  EXPECT_EQ(kept, (std::vector<double>{0, 4, 8}));
  EXPECT_EQ(s.stats().scans, 3u);
  EXPECT_EQ(s.leftOut(), 8u);
  EXPECT_EQ(s.describe(), "list, one scan in 4");
  EXPECT_DOUBLE_EQ(s.fractionRead(), 1.0);
}

TEST(ThrottledScanSource, AKeptScanCarriesTheOdometryOfTheScansLeftOut)
{
  // Random increments, composed one by one (the slow version) between the kept scans.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::vector<std::optional<CPose2D>> inc;
  for (int k = 0; k < 30; k++) inc.emplace_back(CPose2D(u(rng), u(rng), 3 * u(rng)));
  for (size_t every : {1u, 2u, 3u, 7u})
  {
    auto s = throttleScans(std::make_unique<ListSource>(inc), every);
    sensor::ScanInput in;
    size_t expected_index = 0;
    while (s->next(in))
    {
      const size_t k = static_cast<size_t>(secondOf(in));
      ASSERT_EQ(k, expected_index);
      CPose2D motion;
      for (size_t j = k == 0 ? 0 : k - every + 1; j <= k; j++) motion = motion + *inc[j];
      ASSERT_TRUE(in.odometry_increment);
      EXPECT_NEAR(in.odometry_increment->x(), motion.x(), 1e-12) << "every " << every << ", scan " << k;
      EXPECT_NEAR(in.odometry_increment->y(), motion.y(), 1e-12);
      EXPECT_NEAR(std::remainder(in.odometry_increment->phi() - motion.phi(), 2 * M_PI), 0, 1e-12);
      expected_index += every;
    }
    EXPECT_EQ(expected_index, (30 + every - 1) / every * every) << "every " << every;
  }
}

TEST(ThrottledScanSource, AScanLeftOutWithoutOdometryLeavesTheNextKeptOneWithout)
{
  // Scan 4 (left out) has no odometry: scan 6 has none, scan 9's motion is 7-9's, known again.
  std::vector<std::optional<CPose2D>> inc(12, CPose2D(0.1, 0, 0));
  inc[4].reset();
  ThrottledScanSource s(std::make_unique<ListSource>(inc), 3);
  sensor::ScanInput in;
  std::vector<bool> known;
  std::vector<double> forward;
  while (s.next(in))
  {
    known.push_back(in.odometry_increment.has_value());
    forward.push_back(in.odometry_increment ? in.odometry_increment->x() : 0.0);
  }
  EXPECT_EQ(known, (std::vector<bool>{true, true, false, true}));
  EXPECT_NEAR(forward[0], 0.1, 1e-12);
  EXPECT_NEAR(forward[1], 0.3, 1e-12);
  EXPECT_NEAR(forward[3], 0.3, 1e-12);
}

TEST(ThrottledScanSource, OneKeepsTheSourceAndZeroIsRefused)
{
  auto inner = std::make_unique<ListSource>(std::vector<std::optional<CPose2D>>(3));
  const ScanSource* raw = inner.get();
  EXPECT_EQ(throttleScans(std::move(inner), 1).get(), raw);
  EXPECT_THROW(throttleScans(std::make_unique<ListSource>(std::vector<std::optional<CPose2D>>(3)), 0),
               std::invalid_argument);
}

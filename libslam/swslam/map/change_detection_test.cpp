// detectChanges on a room surveyed twice, the second time with one post taken away and another
// put elsewhere, its scans taken at poses a few centimetres off: the two posts are the only
// changes; a survey of the unchanged room reports none.
#include <swslam/map/builder.h>
#include <swslam/map/change_detection.h>
#include <swslam/map/change_picture.h>
#include <swslam/map/map_picture.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "map_test_support.h"
#include "test_support.h"

using namespace swslam;
using namespace swslam::map;
using mrpt::poses::CPose2D;

namespace
{
MapParams roomParams()
{
  MapParams p = test::smallMapParams(12);
  p.resolution = 0.2;
  return p;
}

/** The room scanned from poses around a loop (0.2 m cells), each pose moved by `pose_error`;
 * `map`, if given, gets the same scans. */
SurveyEvidence survey(const test::World& world, double pose_error, unsigned seed, MapBuilder* map = nullptr)
{
  SurveyEvidence evidence(roomParams());
  std::mt19937 rng(seed);
  std::normal_distribution<double> e(0, pose_error);
  for (int k = 0; k < 24; k++)
  {
    const double a = 2 * M_PI * k / 24;
    const CPose2D truth(4.5 * std::cos(a), 2.5 * std::sin(a), a + M_PI / 2);
    const auto obs = test::simulateObservation(world, truth, 541, 1.5 * M_PI, 30, 0.01, rng);
    const CPose2D pose(truth.x() + e(rng), truth.y() + e(rng), truth.phi() + 0.15 * e(rng));
    evidence.insert(static_cast<size_t>(k), obs, pose);
    if (map) map->insert(static_cast<size_t>(k), obs, pose);
  }
  return evidence;
}
}  // namespace

TEST(ChangeDetection, APostTakenAwayAndOnePutElsewhereAreTheOnlyChanges)
{
  test::World before = test::roomWorld(), after = test::roomWorld();
  before.circles.push_back({0.5, 1.0, 0.6});   // taken away
  after.circles.push_back({-2.0, 0.5, 0.6});   // put here
  const auto report = detectChanges(survey(before, 0.0, 1), survey(after, 0.02, 2));
  ASSERT_EQ(report.regions.size(), 2u);
  EXPECT_EQ(report.count(ChangeKind::Appeared), 1u);
  EXPECT_EQ(report.count(ChangeKind::Disappeared), 1u);
  const ChangeRegion& put = report.regions[0];
  const ChangeRegion& taken = report.regions[1];
  EXPECT_EQ(put.kind, ChangeKind::Appeared);
  EXPECT_LT(std::hypot(put.x + 2.0, put.y - 0.5), 0.6) << put.x << " " << put.y;
  EXPECT_LT(std::hypot(taken.x - 0.5, taken.y - 1.0), 0.6) << taken.x << " " << taken.y;
  EXPECT_GE(put.extent(), 0.5);
  EXPECT_LE(put.extent(), 1.6);
  EXPECT_GT(report.compared_cells, 1000u);
  EXPECT_NEAR(report.area(ChangeKind::Appeared), put.area, 1e-12);
}

TEST(ChangeDetection, AnUnchangedPlaceSurveyedAgainReportsNothing)
{
  const test::World room = test::roomWorld();
  const auto report = detectChanges(survey(room, 0.0, 1), survey(room, 0.02, 3));
  EXPECT_TRUE(report.regions.empty()) << report.regions.size() << " regions, first at " << report.regions[0].x
                                      << ", " << report.regions[0].y;
}

TEST(ChangeDetection, EvidenceCountsEachHitAndCrossingOnceAndOtherResolutionsAreRefused)
{
  // One ray straight ahead to a wall 3 m off: its end cell hit once, the cells before it
  // crossed once, nothing beyond.
  SurveyEvidence one(roomParams());
  const auto scan = test::makeScan({3.0, -1}, 0.01, 30);  // the second ray: no return
  one.insert(0, scan, CPose2D(0.1, 0.1, 0));
  EXPECT_EQ(one.hits(15, 0), 1);  // x = 3.1 m: cell 15 at 0.2 m
  EXPECT_EQ(one.crossings(15, 0), 0);
  EXPECT_EQ(one.crossings(7, 0), 1);
  EXPECT_EQ(one.hits(7, 0), 0);
  EXPECT_EQ(one.crossings(20, 0), 0);
  MapParams finer = roomParams();
  finer.resolution = 0.1;
  EXPECT_THROW(detectChanges(one, SurveyEvidence(finer)), std::invalid_argument);
  EXPECT_TRUE(detectChanges(one, one).regions.empty());
}

TEST(ChangeDetection, ThePictureAndTheTableShowEachRegion)
{
  test::World before = test::roomWorld(), after = test::roomWorld();
  before.circles.push_back({0.5, 1.0, 0.6});
  MapBuilder map(roomParams());
  const SurveyEvidence now = survey(after, 0.02, 2, &map);
  const auto grid = map.snapshot();
  const auto report = detectChanges(survey(before, 0.0, 1), now);
  ASSERT_EQ(report.regions.size(), 1u);
  const std::string table = formatChangeReport(report);
  EXPECT_NE(table.find("Disappeared (occupied before, free now): 1 regions"), std::string::npos) << table;
  EXPECT_NE(table.find("| disappeared | "), std::string::npos) << table;
  // The region's centroid is painted red; a cell far from it is not.
  MapPictureLayout layout;
  drawMapPicture(grid, Overlay(), &layout);
  const auto img = drawChangePicture(grid, Overlay(), report);
  const auto& cell = report.regions[0].cells[0];
  const auto at = layout.view.toImage((cell.first + 0.5) * report.resolution, (cell.second + 0.5) * report.resolution);
  const auto channel = [&](unsigned c) { return img.at<uint8_t>(static_cast<unsigned>(at.x), static_cast<unsigned>(at.y), c); };
  EXPECT_EQ(channel(2), 220);  // MRPT's images are BGR
  EXPECT_EQ(channel(1), 0);
  EXPECT_EQ(channel(0), 0);
}

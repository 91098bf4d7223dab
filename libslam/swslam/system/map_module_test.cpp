// MapModule: a re-insertion removes the nodes merged into others (their scans leave the map
// exactly: the map is the one built without them); two re-insertions merged into one (a map
// thread that fell behind) keep the later one's removals.
#include <swslam/system/map_module.h>

#include <mrpt/poses/CPose2D.h>

#include <gtest/gtest.h>

#include "map_test_support.h"

namespace swslam::system
{
namespace
{
using mrpt::poses::CPose2D;

MapInsert insertOf(size_t id, const CPose2D& pose)
{
  auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>(test::makeScan({3.0, 5.0, 4.0, 2.5}, M_PI));
  return MapInsert{id, id, obs, pose};
}

void insertThree(MapModule& m)
{
  m.handle(insertOf(0, CPose2D(0, 0, 0)));
  m.handle(insertOf(1, CPose2D(0.5, 0.2, 0.3)));
  m.handle(insertOf(2, CPose2D(1.0, -0.4, -0.2)));
}
}  // namespace

TEST(MapModule, AReinsertionRemovesTheMergedNodesExactly)
{
  MapModule m(test::smallMapParams(10));
  insertThree(m);
  MapReinsert re;
  re.removed = {1};
  re.poses = {{0, CPose2D(0, 0, 0)}, {2, CPose2D(1.0, -0.4, -0.2)}};
  m.handle(re);
  EXPECT_EQ(m.builder().nodeCount(), 2u);

  // The same map built without node 1, with node 0 where it went.
  MapModule without(test::smallMapParams(10));
  without.handle(insertOf(0, CPose2D(0, 0, 0)));
  without.handle(insertOf(2, CPose2D(1.0, -0.4, -0.2)));
  EXPECT_EQ(test::differingCells(m.builder().snapshot(), without.builder().snapshot()), 0u);
}

TEST(MapModule, MergedReinsertionsKeepTheirRemovals)
{
  MapReinsert first, later;
  first.poses = {{0, CPose2D(0.1, 0, 0)}, {1, CPose2D(0.6, 0.2, 0.3)}};
  later.removed = {1};
  later.poses = {{2, CPose2D(1.1, -0.4, -0.2)}};
  MapModule::merge(first, std::move(later));
  EXPECT_EQ(first.removed, std::vector<map::MapNodeId>{1});
  EXPECT_EQ(first.poses.count(1), 0u) << "a removed node is not re-inserted";
  EXPECT_EQ(first.poses.size(), 2u);

  MapModule m(test::smallMapParams(10));
  insertThree(m);
  m.handle(first);
  EXPECT_EQ(m.builder().nodeCount(), 2u);
}

}  // namespace swslam::system

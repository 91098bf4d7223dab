#include <swslam/plicp/reference_store.h>

#include <gtest/gtest.h>

#include <random>
#include <thread>

#include "test_support.h"

using namespace swslam;
using swslam::plicp::ReferenceScan;
using swslam::plicp::ReferenceStore;

namespace
{
std::shared_ptr<const ReferenceScan> roomScan(size_t k, const plicp::PlicpParams& params)
{
  std::mt19937 rng(static_cast<unsigned>(k));
  const mrpt::poses::CPose2D pose(-2 + 0.3 * static_cast<double>(k), 1, 0.1 * static_cast<double>(k));
  return std::make_shared<const ReferenceScan>(
      sensor::scanFromObservation(test::simulateObservation(test::roomWorld(), pose, 361, 1.5 * M_PI, 30, 0.03, rng)),
      params);
}

/** Whether two reference scans match a scan to the same numbers. */
void expectSameMatches(const ReferenceScan& a, const ReferenceScan& b, const sensor::Scan& cur)
{
  const plicp::PlicpParams p;
  const auto ma = plicp::matchScans(a, cur, mrpt::poses::CPose2D(0.1, 0, 0), p);
  const auto mb = plicp::matchScans(b, cur, mrpt::poses::CPose2D(0.1, 0, 0), p);
  ASSERT_TRUE(ma.ok());
  EXPECT_EQ(ma.pose, mb.pose);
  EXPECT_EQ(ma.covariance, mb.covariance);
  EXPECT_EQ(ma.correspondences, mb.correspondences);
  EXPECT_EQ(a.index.pseudo, b.index.pseudo);
  EXPECT_EQ(a.index.segment_lo, b.index.segment_lo);
}

// Adds room scans 0..count-1 as nodes 0..count-1; returns what was added.
std::vector<std::shared_ptr<const ReferenceScan>> addRoomScans(ReferenceStore& store, const plicp::PlicpParams& params,
                                                               size_t count)
{
  std::vector<std::shared_ptr<const ReferenceScan>> added;
  for (size_t k = 0; k < count; k++)
  {
    added.push_back(roomScan(k, params));
    store.add(k, added.back());
  }
  return added;
}
}  // namespace

TEST(ReferenceStore, KeepsTheLastUsedAndRebuildsTheOthersBitForBit)
{
  const plicp::PlicpParams params;
  ReferenceStore store(params, 3);
  const auto originals = addRoomScans(store, params, 8);
  EXPECT_EQ(store.size(), 8u);
  EXPECT_EQ(store.builtCount(), 3u);
  // The last three added are the ones kept: the same objects.
  EXPECT_EQ(store.get(7), originals[7]);
  EXPECT_EQ(store.get(5), originals[5]);
  // An older one is rebuilt: another object, the same scan and tables.
  const auto rebuilt = store.get(0);
  EXPECT_NE(rebuilt, originals[0]);
  expectSameMatches(*rebuilt, *originals[0], originals[1]->scan);
  EXPECT_EQ(store.builtCount(), 3u);
  // 0, 5, 7 were used last: 6 was dropped, 0 is kept.
  EXPECT_EQ(store.get(0), rebuilt);
  EXPECT_NE(store.get(6), originals[6]);
  // Compact: 8 bytes a ray for the nodes not kept.
  EXPECT_LT(store.bytes(), 3 * plicp::referenceScanBytes(*originals[0]) + 8 * (8 * 361 + 400));
}

TEST(ReferenceStore, RefusesNodesOutOfOrderAndUnknownIds)
{
  const plicp::PlicpParams params;
  ReferenceStore store(params);
  EXPECT_THROW(store.add(1, roomScan(0, params)), std::invalid_argument);
  EXPECT_THROW(store.add(0, nullptr), std::invalid_argument);
  plicp::PlicpParams other = params;
  other.min_segment_length = 2 * params.min_segment_length + 0.1;
  EXPECT_THROW(store.add(0, roomScan(0, other)), std::invalid_argument);
  store.add(0, roomScan(0, params));
  EXPECT_THROW(store.get(1), std::out_of_range);
  EXPECT_THROW(ReferenceStore(params, 0), std::invalid_argument);
}

TEST(ReferenceStore, AReleasedNodeKeepsItsIdButNotItsScan)
{
  const plicp::PlicpParams params;
  ReferenceStore store(params, 3);
  addRoomScans(store, params, 3);
  const size_t before = store.bytes();
  store.release(2);  // kept built: dropped too
  EXPECT_THROW(store.get(2), std::out_of_range);
  EXPECT_EQ(store.builtCount(), 2u);
  EXPECT_LT(store.bytes(), before);
  store.addReleased(3);  // a restored merged node: an id, no scan
  EXPECT_THROW(store.get(3), std::out_of_range);
  EXPECT_THROW(store.addReleased(5), std::invalid_argument);
  store.add(4, roomScan(4, params));
  EXPECT_EQ(store.size(), 5u);
  EXPECT_NO_THROW(store.get(0));
  EXPECT_THROW(store.release(9), std::out_of_range);
}

TEST(ReferenceStore, TwoThreadsGetTheSameScans)
{
  const plicp::PlicpParams params;
  ReferenceStore store(params, 2);
  const auto originals = addRoomScans(store, params, 6);
  auto reader = [&](size_t offset, size_t* mismatches) {
    for (size_t round = 0; round < 200; round++)
    {
      const size_t id = (round + offset) % 6;
      if (store.get(id)->scan.points != originals[id]->scan.points) (*mismatches)++;
    }
  };
  size_t m1 = 0, m2 = 0;
  std::thread a(reader, 0, &m1), b(reader, 3, &m2);
  a.join();
  b.join();
  EXPECT_EQ(m1 + m2, 0u);
  EXPECT_LE(store.builtCount(), 2u);
}

// The fraction of a log read: against the uncompressed size of a gzip rawlog (MRPT reports the
// uncompressed position but the compressed size: 100% at a third of lake-short).
#include <swslam/io/read_progress.h>

#include <swslam/io/rawlog_reader.h>

#include <gtest/gtest.h>

#include <fstream>

#include "test_support.h"

using namespace swslam::io;

TEST(ReadProgress, GzipFractionAgainstTheTrailersSizeModulo4GiB)
{
  EXPECT_DOUBLE_EQ(gzipFraction(50, 100), 0.5);
  EXPECT_DOUBLE_EQ(gzipFraction(100, 100), 1.0);
  const uint64_t big = 5'000'000'000ull, wrapped = big % (uint64_t(1) << 32);
  EXPECT_DOUBLE_EQ(gzipFraction(big, wrapped), 1.0);             // past 4 GiB, at the end
  EXPECT_LT(gzipFraction(wrapped + 1, wrapped), 1.0);            // past the wrapped size: not done
  EXPECT_DOUBLE_EQ(gzipFraction(0, 0), 1.0);                     // an empty stream
}

TEST(ReadProgress, ACompressedRawlogIsAThirdReadAfterAThirdOfItsEntries)
{
  const std::string path = std::string(SWSLAM_SOURCE_DIR) + "/datasets/lake-short/lake-short.rawlog";
  size_t entries = 0;
  {
    RawlogReader count(path);
    RawlogItem item;
    while (count.next(item)) entries++;
  }
  RawlogReader reader(path);
  RawlogItem item;
  for (size_t k = 0; k < entries / 3; k++) ASSERT_TRUE(reader.next(item));
  EXPECT_NEAR(reader.fractionRead(), 1.0 / 3, 0.05);
  while (reader.next(item)) {}
  EXPECT_DOUBLE_EQ(reader.fractionRead(), 1.0);
}

TEST(ReadProgress, APlainFileAgainstItsSizeAndAMissingOneAsDone)
{
  const std::string path = swslam::test::tempDir("read_progress") + "/plain.txt";
  std::ofstream(path) << std::string(200, 'x');
  const ReadProgress plain(path);
  EXPECT_DOUBLE_EQ(plain.fraction(50), 0.25);
  EXPECT_DOUBLE_EQ(ReadProgress("/nonexistent/file").fraction(10), 1.0);
}

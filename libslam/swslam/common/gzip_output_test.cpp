// Gzip output through a checked stream: what is written reads back, and a disk that refuses
// the data is an error, with no file left.
#include <swslam/common/gzip_output.h>

#include <mrpt/io/CFileGZInputStream.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <random>


#include "test_support.h"

using namespace swslam::common;
namespace fs = std::filesystem;

namespace
{
/** Bytes that compress little (random) and a lot (repeated). */
std::string content(size_t n)
{
  std::mt19937 rng(7);
  std::string s(n, '\0');
  for (size_t i = 0; i < n; i++) s[i] = i % 3 == 0 ? 'a' : static_cast<char>(rng());
  return s;
}
}  // namespace

TEST(GzipOutput, WhatIsWrittenReadsBackThroughMrpt)
{
  const std::string dir = swslam::test::tempDir("gzip_output");
  for (const size_t n : {size_t(0), size_t(10), size_t(300000)})
  {
    const std::string path = dir + "/x.gz", data = content(n);
    writeGzipAtomically(path, 1, [&](mrpt::io::CStream& out) {
      out.Write(data.data(), data.size() / 2);
      out.Write(data.data() + data.size() / 2, data.size() - data.size() / 2);
      EXPECT_EQ(out.getPosition(), data.size());
    });
    mrpt::io::CFileGZInputStream in(path);
    std::string back(n + 10, '\0');
    EXPECT_EQ(in.Read(back.data(), back.size()), n);
    back.resize(n);
    EXPECT_EQ(back, data);
  }
  EXPECT_THROW(writeGzipAtomically(dir + "/y.gz", 10, [](mrpt::io::CStream&) {}), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir + "/y.gz"));
}

TEST(GzipOutput, AFullDiskIsANamedFailureAndLeavesNoFile)
{
  // MRPT's CFileGZOutputStream ignores gzclose()'s failure: the last block was lost silently.
  const std::string dir = swslam::test::tempDir("gzip_output_full");
  std::string what;
  swslam::test::withFileSizeLimit(16384, [&] {
    for (const size_t n : {size_t(30000), size_t(3000000)})  // refused at the end; on the way
    {
      try
      {
        writeGzipAtomically(dir + "/map.gridmap.gz", 1, [&](mrpt::io::CStream& out) {
          const std::string data = content(n);
          out.Write(data.data(), data.size());
        });
      }
      catch (const std::runtime_error& e)
      {
        what = e.what();
      }
      EXPECT_NE(what.find("cannot write '" + dir + "/map.gridmap.gz': the disk refused the data: File too large"),
                std::string::npos)
          << n << ": " << what;
      EXPECT_TRUE(fs::is_empty(dir)) << n;
      what.clear();
    }
  });
}

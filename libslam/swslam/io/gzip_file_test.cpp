#include <swslam/io/gzip_file.h>

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <zlib.h>

#include "test_support.h"

using namespace swslam::io;

namespace
{
/** 200 kB of lines, as a gzip file (zlib's own writer) at `path`; returns the content. */
std::string writeGzip(const std::string& path)
{
  std::string content;
  for (int k = 0; k < 20000; k++) content += "line " + std::to_string(k * 7919 % 100003) + "\n";
  gzFile f = gzopen(path.c_str(), "wb");
  gzwrite(f, content.data(), static_cast<unsigned>(content.size()));
  gzclose(f);
  return content;
}

std::string bytesOf(const std::string& path)
{
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), {});
}

/** Reads `path` in 1000-byte pieces: the content read, and the error that stopped it. */
std::pair<std::string, std::string> readAll(const std::string& path)
{
  GzipFile file(path);
  std::string out;
  char buf[1000];
  try
  {
    while (const size_t got = file.read(buf, sizeof(buf))) out.append(buf, got);
  }
  catch (const GzipError& e)
  {
    EXPECT_EQ(e.contentRead(), out.size());
    EXPECT_THROW(file.read(buf, sizeof(buf)), GzipError) << "every later read fails too";
    return {out, e.what()};
  }
  EXPECT_EQ(file.position(), out.size());
  return {out, ""};
}
}  // namespace

TEST(GzipFile, ReadsGzipAndPlainFiles)
{
  const auto dir = swslam::test::tempDir("gzip_file");
  const std::string content = writeGzip(dir + "/a.gz");
  EXPECT_EQ(readAll(dir + "/a.gz"), std::make_pair(content, std::string()));
  std::ofstream(dir + "/plain.txt") << content;
  EXPECT_EQ(readAll(dir + "/plain.txt"), std::make_pair(content, std::string()));
  EXPECT_THROW(GzipFile(dir + "/missing.gz"), std::runtime_error);
}

TEST(GzipFile, ACutStreamIsAnErrorAfterTheContentBeforeTheCut)
{
  const auto dir = swslam::test::tempDir("gzip_file_cut");
  const std::string content = writeGzip(dir + "/a.gz");
  const std::string bytes = bytesOf(dir + "/a.gz");
  for (const size_t keep : {bytes.size() / 2, bytes.size() - 4, bytes.size() - 1})
  {
    std::ofstream(dir + "/cut.gz", std::ios::binary) << bytes.substr(0, keep);
    const auto [read, error] = readAll(dir + "/cut.gz");
    EXPECT_EQ(error, "the gzip stream is cut short after " + std::to_string(read.size()) +
                         " bytes of content (a truncated file)")
        << "kept " << keep;
    EXPECT_EQ(read, content.substr(0, read.size()));
    if (keep == bytes.size() / 2) EXPECT_GT(read.size(), content.size() / 4);
  }
}

TEST(GzipFile, CorruptDataIsAnErrorNamingZlibsFinding)
{
  const auto dir = swslam::test::tempDir("gzip_file_flip");
  writeGzip(dir + "/a.gz");
  std::string bytes = bytesOf(dir + "/a.gz");
  for (size_t at = bytes.size() / 3; at < bytes.size() / 3 + 16; at++) bytes[at] = static_cast<char>(~bytes[at]);
  std::ofstream(dir + "/flipped.gz", std::ios::binary) << bytes;
  const auto [read, error] = readAll(dir + "/flipped.gz");
  EXPECT_EQ(error.rfind("corrupt gzip data after ", 0), 0u) << error;
  EXPECT_NE(error.find("(zlib: "), std::string::npos) << error;
}

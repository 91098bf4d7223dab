// Files compressed whole with zstd: decompressed as they were; not zstd, cut short or past
// the bound, a named error that leaves no output file.
#include <swslam/io/zstd_file.h>

#include "test_support.h"

#include <zstd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace swslam::io;
using swslam::test::errorOf;
namespace fs = std::filesystem;

namespace
{
std::string temp(const std::string& name) { return (fs::temp_directory_path() / ("swslam_zstd_" + name)).string(); }

void writeFile(const std::string& path, const std::vector<char>& bytes)
{
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::vector<char> readFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::vector<char> zstdOf(const std::vector<char>& b)
{
  std::vector<char> out(ZSTD_compressBound(b.size()));
  out.resize(ZSTD_compress(out.data(), out.size(), b.data(), b.size(), 3));
  return out;
}

/** 3 MiB of varied bytes (several output blocks). */
std::vector<char> content()
{
  std::vector<char> b(3 << 20);
  for (size_t i = 0; i < b.size(); i++) b[i] = static_cast<char>((i * 2654435761u) >> 13);
  return b;
}
}  // namespace

TEST(ZstdFile, DecompressesAFileAsItWas)
{
  writeFile(temp("in.zstd"), zstdOf(content()));
  decompressZstdFile(temp("in.zstd"), temp("out"));
  EXPECT_TRUE(readFile(temp("out")) == content());
}

TEST(ZstdFile, NotZstdCutShortOrPastTheBoundIsNamedAndLeavesNoFile)
{
  writeFile(temp("text.zstd"), {'h', 'e', 'l', 'l', 'o'});
  EXPECT_NE(errorOf([&] { decompressZstdFile(temp("text.zstd"), temp("out1")); }).find(": corrupt zstd data: "),
            std::string::npos);
  EXPECT_FALSE(fs::exists(temp("out1")));

  auto z = zstdOf(content());
  z.resize(z.size() / 2);
  writeFile(temp("cut.zstd"), z);
  EXPECT_EQ(errorOf([&] { decompressZstdFile(temp("cut.zstd"), temp("out2")); }),
            "'" + temp("cut.zstd") + "': its zstd data is cut short (a truncated file)");
  EXPECT_FALSE(fs::exists(temp("out2")));

  writeFile(temp("zeros.zstd"), zstdOf(std::vector<char>(4 << 20, 0)));  // a few hundred bytes
  const std::string e = errorOf([&] { decompressZstdFile(temp("zeros.zstd"), temp("out3"), 1 << 20); });
  EXPECT_NE(e.find("it decompresses to more than 1048576 bytes (at most 1048576, and 32768 times its"),
            std::string::npos)
      << e;
  EXPECT_FALSE(fs::exists(temp("out3")));
}

// Atomic writes: the temporary name a write uses is one isAtomicTemporary() recognizes (a
// killed run's leftovers are found by it), and no other name is.
#include <swslam/common/atomic_file.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>


#include "test_support.h"

using namespace swslam::common;
namespace fs = std::filesystem;

namespace
{
void touch(const std::string& path) { std::ofstream(path) << "x"; }
}  // namespace

TEST(AtomicFile, TheTemporaryNamesOfAtomicWritesAreRecognized)
{
  const std::string dir = swslam::test::tempDir("atomic_file_names");
  std::string seen;
  writeAtomically(dir + "/map.gridmap.gz", [&](const std::string& tmp) {
    seen = fs::path(tmp).filename().string();
    touch(tmp);
  });
  EXPECT_TRUE(isAtomicTemporary(seen)) << seen;
  EXPECT_TRUE(isAtomicTemporary(".trajectory.tmp4242.tum"));
  for (const char* name : {"trajectory.tum", ".swslam.lock", "notes.tmp.txt", ".tmp12", "map.tmp3.png"})
    EXPECT_FALSE(isAtomicTemporary(name)) << name;
}

namespace
{
/** The message of what `f` throws ("" if nothing). */
std::string failureOf(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  return "";
}

/** The files in `dir`. */
size_t filesIn(const std::string& dir)
{
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) n++;
  return n;
}
}  // namespace

TEST(AtomicFile, AFullDiskIsANamedFailureAndLeavesNoFile)
{
  // graph.graph was left as a 0-byte file, without a word, when the disk filled up: its
  // writer checked the stream before closing it, and the data still in the stream's buffer
  // failed to reach the disk when it closed.
  const std::string dir = swslam::test::tempDir("atomic_file_full");
  const std::string small(6000, 'x'), large(100000, 'y');  // within the stream's buffer; beyond it
  swslam::test::withFileSizeLimit(4096, [&] {
    for (const std::string* content : {&small, &large})
    {
      const std::string path = dir + "/graph.graph";
      const std::string text = failureOf([&] { writeTextAtomically(path, *content); });
      EXPECT_NE(text.find("cannot write '" + path + "': the disk refused the data: File too large"), std::string::npos)
          << text;
      const std::string stream = failureOf([&] {
        writeStreamAtomically(path, [&](std::ostream& out) { out << *content; });
      });
      EXPECT_EQ(stream, text);
      EXPECT_FALSE(fs::exists(path));
      EXPECT_EQ(filesIn(dir), 0u) << "a temporary file was left";
    }
    // What fits is written whole.
    writeTextAtomically(dir + "/fits.txt", "fits\n");
  });
  EXPECT_EQ(fs::file_size(dir + "/fits.txt"), 5u);
}

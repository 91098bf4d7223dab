// Atomic writes: the temporary name a write uses is one isAtomicTemporary() recognizes (a
// killed run's leftovers are found by it), and no other name is.
#include <swslam/common/atomic_file.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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

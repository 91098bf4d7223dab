// The output folder: taken by one run at a time, its killed run's temporary files removed,
// the previous run's outputs removed once, just before this run writes.
#include <swslam/app/output_folder.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "test_support.h"

using namespace swslam;
using namespace swslam::app;
namespace fs = std::filesystem;

namespace
{
void touch(const std::string& path) { std::ofstream(path) << "x"; }

std::string errorOf(const std::string& dir)
{
  try
  {
    OutputFolder f(dir);
  }
  catch (const std::invalid_argument& e)
  {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(OutputFolder, OneRunAtATime)
{
  const std::string dir = test::tempDir("output_folder_lock") + "/out";
  {
    OutputFolder first(dir);
    EXPECT_TRUE(fs::is_directory(dir));
    const std::string why = errorOf(dir);
    EXPECT_NE(why.find("another run is writing into it (process "), std::string::npos) << why;
  }
  EXPECT_EQ(errorOf(dir), "") << "the lock goes with its holder";
}

TEST(OutputFolder, AFolderThatCannotBeMadeIsNamed)
{
  const std::string dir = test::tempDir("output_folder_file");
  touch(dir + "/a-file");
  const std::string why = errorOf(dir + "/a-file/out");
  EXPECT_NE(why.find("a-file/out': cannot be created"), std::string::npos) << why;
}

TEST(OutputFolder, AKilledRunsTemporariesGoAtOnceThePreviousOutputsJustBeforeWriting)
{
  const std::string dir = test::tempDir("output_folder_clear");
  for (const char* name : {".trajectory.tmp77.tum", "trajectory.tum", "render.png", "notes.txt"})
    touch(dir + "/" + name);
  OutputFolder f(dir);
  EXPECT_EQ(f.staleRemoved(), 1u);
  EXPECT_FALSE(fs::exists(dir + "/.trajectory.tmp77.tum"));
  EXPECT_TRUE(fs::exists(dir + "/trajectory.tum"));
  f.clearPreviousRun({"trajectory.tum", "render.png", "graph.graph"});
  EXPECT_FALSE(fs::exists(dir + "/trajectory.tum"));
  EXPECT_FALSE(fs::exists(dir + "/render.png"));
  EXPECT_TRUE(fs::exists(dir + "/notes.txt")) << "only the named outputs go";
  touch(dir + "/trajectory.tum");  // this run's own
  f.clearPreviousRun({"trajectory.tum"});
  EXPECT_TRUE(fs::exists(dir + "/trajectory.tum")) << "cleared once only";
}

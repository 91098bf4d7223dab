// The output folder: taken by one run at a time, its killed run's temporary files removed,
// the previous run's outputs removed once, just before this run writes, or replaced as one.
#include <swslam/app/output_folder.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <sys/stat.h>

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

TEST(OutputFolder, ALockFileThatIsNoFileIsNamed)
{
  // "cannot be written: Is a directory" did not say what was a directory.
  const std::string dir = test::tempDir("output_folder_lock_kinds");
  const std::string lock = dir + "/.swslam.lock";
  fs::create_directory(lock);
  EXPECT_EQ(errorOf(dir), "output folder '" + dir + "': its lock file .swslam.lock is a directory, not a file: remove it (" +
                              lock + ")");
  fs::remove(lock);
  ASSERT_EQ(::mkfifo(lock.c_str(), 0644), 0);
  EXPECT_EQ(errorOf(dir), "output folder '" + dir + "': its lock file .swslam.lock is a FIFO, not a file: remove it (" +
                              lock + ")");  // at once: opening a FIFO does not wait for a writer
  fs::remove(lock);
  fs::create_symlink("/nonexistent", lock);
  EXPECT_NE(errorOf(dir).find("its lock file .swslam.lock is a symbolic link"), std::string::npos) << errorOf(dir);
  fs::remove(lock);
  EXPECT_EQ(errorOf(dir), "");
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

namespace
{
/** A writer of `files` into its folder, failing on `fails` (not written). */
std::function<std::vector<map::OutputProblem>(const std::string&)> writer(const std::vector<std::string>& files,
                                                                        const std::string& fails = "")
{
  return [=](const std::string& dir) {
    std::vector<map::OutputProblem> problems;
    for (const auto& f : files)
      if (f == fails)
        problems.push_back({f, "No space left on device"});
      else
        std::ofstream(dir + "/" + f) << "new";
    return problems;
  };
}
std::string contentOf(const std::string& path)
{
  std::ifstream in(path);
  std::string s;
  std::getline(in, s);
  return s;
}
}  // namespace

TEST(OutputFolder, ARunThatWritesEverythingReplacesThePreviousOneWhole)
{
  const std::string dir = test::tempDir("output_folder_replace");
  for (const char* name : {"trajectory.tum", "map.png", "map.bt", "notes.txt"}) touch(dir + "/" + name);
  fs::create_directory(dir + "/" + OutputFolder::kUnfinished);
  OutputFolder f(dir);
  const auto r = f.replaceRun({"trajectory.tum", "map.png", "map.bt"}, writer({"trajectory.tum", "map.png"}));
  EXPECT_TRUE(r.problems.empty());
  EXPECT_FALSE(r.kept_previous);
  EXPECT_EQ(contentOf(dir + "/trajectory.tum"), "new");
  EXPECT_EQ(contentOf(dir + "/map.png"), "new");
  EXPECT_FALSE(fs::exists(dir + "/map.bt")) << "the previous run's output this run did not write";
  EXPECT_TRUE(fs::exists(dir + "/notes.txt")) << "only the named outputs go";
  EXPECT_FALSE(fs::exists(dir + "/" + OutputFolder::kUnfinished)) << "an earlier failure's outputs are older";
  EXPECT_FALSE(fs::exists(dir + "/.swslam-staging"));
}

TEST(OutputFolder, ARunThatCannotWriteAnOutputKeepsThePreviousRunAndPutsItsOwnAside)
{
  const std::string dir = test::tempDir("output_folder_keep");
  for (const char* name : {"trajectory.tum", "map.png"}) touch(dir + "/" + name);
  OutputFolder f(dir);
  const auto r = f.replaceRun({"trajectory.tum", "map.png"}, writer({"trajectory.tum", "map.png"}, "map.png"));
  ASSERT_EQ(r.problems.size(), 1u);
  EXPECT_EQ(r.problems[0].file, "map.png");
  EXPECT_TRUE(r.kept_previous);
  EXPECT_EQ(contentOf(dir + "/trajectory.tum"), "x") << "the previous run's, untouched";
  EXPECT_EQ(contentOf(dir + "/map.png"), "x");
  const std::string aside = dir + "/" + OutputFolder::kUnfinished;
  EXPECT_EQ(contentOf(aside + "/trajectory.tum"), "new") << "what this run wrote is kept too";
  EXPECT_FALSE(fs::exists(aside + "/map.png"));
  EXPECT_FALSE(fs::exists(dir + "/.swslam-staging"));
}

TEST(OutputFolder, AFirstRunThatCannotWriteAnOutputKeepsTheOthersInPlace)
{
  const std::string dir = test::tempDir("output_folder_first");
  OutputFolder f(dir);
  const auto r = f.replaceRun({"trajectory.tum", "map.png"}, writer({"trajectory.tum", "map.png"}, "map.png"));
  EXPECT_EQ(r.problems.size(), 1u);
  EXPECT_FALSE(r.kept_previous) << "no previous run to keep";
  EXPECT_EQ(contentOf(dir + "/trajectory.tum"), "new");
  EXPECT_FALSE(fs::exists(dir + "/" + OutputFolder::kUnfinished));
}

TEST(OutputFolder, AKilledRunsStagingFolderGoesWhenTheFolderIsTaken)
{
  const std::string dir = test::tempDir("output_folder_staging");
  fs::create_directory(dir + "/.swslam-staging");
  touch(dir + "/.swslam-staging/map.png");
  touch(dir + "/.swslam-staging/trajectory.tum");
  OutputFolder f(dir);
  EXPECT_EQ(f.staleRemoved(), 2u);
  EXPECT_FALSE(fs::exists(dir + "/.swslam-staging"));
}

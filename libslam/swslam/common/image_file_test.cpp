// Images written whole or not at all: a PNG the disk cut short is an error, not a file.
#include <swslam/common/image_file.h>

#include <mrpt/img/CImage.h>

#include <gtest/gtest.h>

#include <filesystem>

#include "test_support.h"

using namespace swslam::common;
namespace fs = std::filesystem;

TEST(ImageFile, AnImageTheDiskRefusedIsANamedFailureAndLeavesNoFile)
{
  // The image libraries ignore the failure to close their file: a short PNG was a "success".
  const std::string dir = swslam::test::tempDir("image_file");
  mrpt::img::CImage image(300, 200, mrpt::img::CH_RGB);
  for (int y = 0; y < 200; y++)
    for (int x = 0; x < 300; x++) *image(x, y, 0) = static_cast<uint8_t>((x * 7919 + y * 104729) % 251);
  writeImageAtomically(dir + "/whole.png", image);
  mrpt::img::CImage back;
  ASSERT_TRUE(back.loadFromFile(dir + "/whole.png"));
  EXPECT_EQ(back.getWidth(), 300u);
  std::string what;
  swslam::test::withFileSizeLimit(fs::file_size(dir + "/whole.png") / 2, [&] {
    try
    {
      writeImageAtomically(dir + "/map.png", image);
    }
    catch (const std::runtime_error& e)
    {
      what = e.what();
    }
  });
  EXPECT_NE(what.find("cannot write '" + dir + "/map.png': "), std::string::npos) << what;
  EXPECT_NE(what.find("File too large"), std::string::npos) << what;
  EXPECT_FALSE(fs::exists(dir + "/map.png"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

#include <swslam/io/text_encoding.h>

#include <gtest/gtest.h>

using swslam::io::wideTextEncoding;
using swslam::io::wideTextProblem;

namespace
{
/** `text` (ASCII) in UTF-16, little- or big-endian, with or without a byte order mark. */
std::string utf16(const std::string& text, bool little, bool bom)
{
  std::string out = bom ? (little ? std::string("\xFF\xFE", 2) : std::string("\xFE\xFF", 2)) : "";
  for (char c : text) out += little ? std::string{c, '\0'} : std::string{'\0', c};
  return out;
}

const std::string kLog = "PARAM robot_frontlaser_offset 0.0\nFLASER 3 1.0 1.1 1.2 0 0 0 0 0 0 12.5 host 12.5\n";
}  // namespace

TEST(TextEncoding, AnAsciiOrUtf8LogIsNotWide)
{
  EXPECT_EQ(wideTextEncoding(kLog), "");
  EXPECT_EQ(wideTextEncoding("\xEF\xBB\xBF" + kLog), "");  // UTF-8 with its mark
  EXPECT_EQ(wideTextEncoding(""), "");
  EXPECT_EQ(wideTextProblem(kLog), "");
  // A binary file (a gzip or rawlog read as text) is not taken for UTF-16.
  EXPECT_EQ(wideTextEncoding(std::string("\x1f\x8b\x08\0\0\0\0\0\0\x03\xab\xcd\0\x12\x34\0", 16)), "");
}

TEST(TextEncoding, Utf16IsNamedWithOrWithoutItsMark)
{
  EXPECT_EQ(wideTextEncoding(utf16(kLog, true, true)), "UTF-16LE");
  EXPECT_EQ(wideTextEncoding(utf16(kLog, false, true)), "UTF-16BE");
  EXPECT_EQ(wideTextEncoding(utf16(kLog, true, false)), "UTF-16LE");
  EXPECT_EQ(wideTextEncoding(utf16(kLog, false, false)), "UTF-16BE");
  EXPECT_EQ(wideTextProblem(utf16(kLog, true, true)),
            "is UTF-16LE text (it starts with the byte order mark FF FE), not the ASCII of a log: convert it first "
            "(iconv -f UTF-16 -t UTF-8)");
  EXPECT_EQ(wideTextProblem(utf16(kLog, false, false)),
            "is UTF-16BE text (a NUL byte beside every character), not the ASCII of a log: convert it first "
            "(iconv -f UTF-16 -t UTF-8)");
  EXPECT_EQ(wideTextEncoding(std::string("\xFF\xFE\0\0P\0\0\0", 8)), "UTF-32LE");
}

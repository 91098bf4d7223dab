// SCIP 2.0 encoding: the examples of Hokuyo's SCIP 2.0 specification and of a real
// UTM-30LX-EW's replies, round trips, and the slow positional definition.
#include "scip/scip_encoding.h"

#include <gtest/gtest.h>

#include <random>

namespace swslam::scip
{
namespace
{
/** The definition, digit by digit: sum of (c - 0x30) * 64^position. */
uint64_t slowDecode(const std::string& s)
{
  uint64_t v = 0, weight = 1;
  for (auto it = s.rbegin(); it != s.rend(); ++it, weight *= 64) v += (*it - 0x30) * weight;
  return v;
}

TEST(ScipEncoding, SpecificationExamples)
{
  // SCIP 2.0 specification, "data encoding": 2 and 3 characters.
  EXPECT_EQ(encode(1234, 2), "CB");
  EXPECT_EQ(decode("CB"), 1234u);
  EXPECT_EQ(encode(5432, 3), "1Dh");
  EXPECT_EQ(decode("1Dh"), 5432u);
  // 4 characters (timestamps), by hand: 1000 = 001111 101000 -> '0' '0' '?' 'X'.
  EXPECT_EQ(encode(1000, 4), "00?X");
  EXPECT_EQ(encode(0, 4), "0000");
  EXPECT_EQ(encode(0xFFFFFF, 4), "oooo");
  EXPECT_EQ(decode("oooo"), 0xFFFFFFu);
}

TEST(ScipEncoding, RoundTripsAndMatchesTheDefinition)
{
  for (uint32_t v = 0; v < 4096; v++)
  {
    ASSERT_EQ(decode(encode(v, 2)), v);
    ASSERT_EQ(slowDecode(encode(v, 2)), v);
  }
  std::mt19937 rng(5);
  for (int chars = 1; chars <= 4; chars++)
  {
    std::uniform_int_distribution<uint32_t> value(0, (1u << (6 * chars)) - 1);
    for (int i = 0; i < 2000; i++)
    {
      const uint32_t v = value(rng);
      const std::string s = encode(v, chars);
      ASSERT_EQ(s.size(), static_cast<size_t>(chars));
      ASSERT_EQ(decode(s), v);
      ASSERT_EQ(slowDecode(s), v);
      for (char c : s) ASSERT_TRUE(c >= 0x30 && c <= 0x6F) << s;
    }
  }
  const std::vector<uint32_t> ranges{0, 1, 23, 5432, 60000, 262143};
  std::string text;
  for (uint32_t r : ranges) text += encode(r, 3);
  EXPECT_EQ(decodeValues(text, 3), ranges);
}

TEST(ScipEncoding, RejectsWhatDoesNotFit)
{
  EXPECT_THROW(encode(4096, 2), std::invalid_argument);
  EXPECT_THROW(encode(1u << 18, 3), std::invalid_argument);
  EXPECT_THROW(encode(1u << 24, 4), std::invalid_argument);
  EXPECT_THROW(encode(1, 0), std::invalid_argument);
  EXPECT_THROW(encode(1, 5), std::invalid_argument);
  EXPECT_THROW(decode(""), std::invalid_argument);
  EXPECT_THROW(decode("00000"), std::invalid_argument);
  EXPECT_THROW(decode("0 "), std::invalid_argument);  // below 0x30
  EXPECT_THROW(decode("p"), std::invalid_argument);   // above 0x6F
  EXPECT_THROW(decodeValues("1Dh1", 3), std::invalid_argument);
}

TEST(ScipChecksum, StatusLinesOfTheSpecification)
{
  EXPECT_EQ(checksum("00"), 'P');  // "00P": command received
  EXPECT_EQ(checksum("99"), 'b');  // "99b": scan data follows
  EXPECT_EQ(checksum("0E"), 'e');  // "SCIP2.0" answered "0Ee" in SCIP 2.0 mode
  EXPECT_EQ(dataLine("00"), "00P\n");
}

TEST(ScipChecksum, ParameterLinesOfARealUtm30lx)
{
  // The PP reply of a UTM-30LX-EW: the ';' is not summed.
  EXPECT_EQ(infoLine("MODL:UTM-30LX-EW"), "MODL:UTM-30LX-EW;I\n");
  EXPECT_EQ(infoLine("DMIN:23"), "DMIN:23;7\n");
  EXPECT_EQ(infoLine("DMAX:60000"), "DMAX:60000;J\n");
  EXPECT_EQ(infoLine("ARES:1440"), "ARES:1440;^\n");
  EXPECT_EQ(infoLine("AMIN:0"), "AMIN:0;?\n");
  EXPECT_EQ(infoLine("AMAX:1080"), "AMAX:1080;Z\n");
  EXPECT_EQ(infoLine("AFRT:540"), "AFRT:540;0\n");
  EXPECT_EQ(infoLine("SCAN:2400"), "SCAN:2400;U\n");
}

TEST(ScipChecksum, IsTheLowSixBitsOfTheByteSum)
{
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> ch(0x20, 0x7E), len(0, 80);
  for (int i = 0; i < 500; i++)
  {
    std::string s(static_cast<size_t>(len(rng)), ' ');
    unsigned sum = 0;
    for (char& c : s) sum += static_cast<unsigned>(c = static_cast<char>(ch(rng)));
    ASSERT_EQ(checksum(s), static_cast<char>(0x30 + sum % 64)) << s;
  }
}

TEST(ScipBlocks, SplitsIntoLinesOfSixtyFourCharacters)
{
  // A UTM-30LX scan: 1081 ranges of 3 characters = 50 full lines and one of 43.
  const std::string data(1081 * 3, '0');
  const auto blocks = splitBlocks(data);
  ASSERT_EQ(blocks.size(), 51u);
  for (size_t i = 0; i + 1 < blocks.size(); i++) EXPECT_EQ(blocks[i].size(), 64u);
  EXPECT_EQ(blocks.back().size(), 43u);
  EXPECT_TRUE(splitBlocks("").empty());
  EXPECT_EQ(splitBlocks(std::string(128, 'a')).size(), 2u);
}

}  // namespace
}  // namespace swslam::scip

// The CDR writer against bytes laid out by hand from the specification (XCDR1): the header,
// alignment from the header's end, strings with their NUL, both byte orders.
#include <swslam/io/cdr_writer.h>

#include <gtest/gtest.h>

using swslam::io::CdrWriter;

TEST(CdrWriter, AlignsEachPrimitiveToItsSizeInEitherByteOrder)
{
  CdrWriter le;
  le.put<uint8_t>(7).put<uint32_t>(0x01020304).str("ab").put<double>(1.0);
  const std::vector<uint8_t> want_le{0, 1, 0, 0,              // header: CDR_LE
                                     7, 0, 0, 0,              // u8, padding to 4
                                     4, 3, 2, 1,              // u32
                                     3, 0, 0, 0, 'a', 'b', 0, // string: length with its NUL
                                     0,                       // padding to 8 (from the header's end)
                                     0, 0, 0, 0, 0, 0, 0xF0, 0x3F};
  EXPECT_EQ(le.bytes(), want_le);
  CdrWriter be(true);
  be.put<uint16_t>(0x0102).floats({1.0f});
  const std::vector<uint8_t> want_be{0, 0, 0, 0, 1, 2, 0, 0, 0, 0, 0, 1, 0x3F, 0x80, 0, 0};
  EXPECT_EQ(be.bytes(), want_be);
}

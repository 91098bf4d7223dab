// The CDR cursor: both byte orders, alignment counted from the payload, every length checked.
#include <swslam/io/cdr_reader.h>
#include <swslam/io/cdr_writer.h>

#include "test_support.h"

#include <gtest/gtest.h>

using namespace swslam::io;
using swslam::test::errorOf;

TEST(CdrReader, ReadsBothByteOrdersAlignedFromThePayload)
{
  for (bool big : {false, true})
  {
    CdrWriter out(big);
    out.put<uint32_t>(7).str("ab").put<double>(-2.5).put<float>(1.25f).put<int32_t>(-3);
    auto& b = out.bytes();
    // u32 at payload 0, the string's length at 4 and "ab\0" at 8-10, padding to 16 for the double.
    ASSERT_EQ(b.size(), 4u + 16 + 8 + 4 + 4);
    CdrReader c(b.data(), b.size());
    EXPECT_EQ(c.bigEndian(), big);
    EXPECT_EQ(c.u32(), 7u);
    EXPECT_EQ(c.string(), "ab");
    EXPECT_EQ(c.f64(), -2.5);
    EXPECT_EQ(c.f32(), 1.25f);
    EXPECT_EQ(c.i32(), -3);
    EXPECT_NO_THROW(c.expectEnd());
  }
  const std::vector<uint8_t> be{0, 0, 0, 0, 0x12, 0x34, 0x56, 0x78};
  EXPECT_EQ(CdrReader(be.data(), be.size()).u32(), 0x12345678u);
}

TEST(CdrReader, AnythingPastTheBytesIsANamedError)
{
  const std::vector<uint8_t> two{0, 1};
  EXPECT_EQ(errorOf([&] { CdrReader(two.data(), two.size()); }),
            "CDR byte 4 of 2: shorter than the 4-byte encapsulation header");
  const std::vector<uint8_t> pl{0, 3, 0, 0};
  EXPECT_NE(errorOf([&] { CdrReader(pl.data(), pl.size()); }).find("is not plain CDR"), std::string::npos);

  CdrWriter out(false);
  out.put<uint32_t>(1);
  auto b = out.bytes();
  CdrReader c(b.data(), b.size());
  c.u32();
  EXPECT_EQ(errorOf([&] { c.f64(); }), "CDR byte 8 of 8: a value of 8 bytes runs past the message's end");

  CdrWriter s(false);
  s.put<uint32_t>(0xFFFFFFF0u);  // a string's length far past the end
  auto sb = s.bytes();
  CdrReader cs(sb.data(), sb.size());
  EXPECT_EQ(errorOf([&] { cs.string(); }), "CDR byte 8 of 8: a string of 4294967280 bytes, but 0 are left");

  CdrWriter q(false);
  q.put<uint32_t>(1000).put<uint32_t>(0);
  auto qb = q.bytes();
  CdrReader cq(qb.data(), qb.size());
  EXPECT_EQ(errorOf([&] { cq.sequenceLength(72); }),
            "CDR byte 8 of 12: a sequence of 1000 elements of at least 72 bytes, but 4 bytes are left");

  CdrWriter nul(false);
  nul.put<uint32_t>(2).put<uint8_t>('a').put<uint8_t>('b');
  auto nb = nul.bytes();
  CdrReader cn(nb.data(), nb.size());
  EXPECT_NE(errorOf([&] { cn.string(); }).find("does not end in NUL"), std::string::npos);

  CdrWriter extra(false);
  extra.put<uint32_t>(1).put<uint32_t>(2);
  auto eb = extra.bytes();
  CdrReader ce(eb.data(), eb.size());
  ce.u32();
  EXPECT_EQ(errorOf([&] { ce.expectEnd(); }), "CDR byte 8 of 12: 4 bytes past the message's end");
}

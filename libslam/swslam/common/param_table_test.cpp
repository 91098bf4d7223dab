// A module's key table (param_table.h): strict loading, ranges, rules, and the written form.
#include <swslam/common/param_table.h>

#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

using namespace swslam::common;

namespace
{
enum class Mode
{
  Slow,
  Fast
};

struct Demo
{
  double length = 0.5;
  double turn = mrpt::DEG2RAD(10.0);
  int count = 3;
  size_t window = 30;
  bool on = true;
  Mode mode = Mode::Slow;
  std::string label = "laser";
  double low = 0.2, high = 0.7;

  static const ParamTable<Demo>& table()
  {
    static const auto t = ParamTable<Demo>("demo", "A demo section.")
                              .real("length", &Demo::length, "m", above(0), "a length", Tier::User)
                              .angle("turn_DEG", &Demo::turn, between(0, 180), "a turn")
                              .integer("count", &Demo::count, "", atLeast(0), "a count")
                              .integer("window", &Demo::window, "", atLeast(2), "a size")
                              .flag("on", &Demo::on, "a switch")
                              .choice("mode", &Demo::mode, {{"slow", Mode::Slow}, {"fast", Mode::Fast}}, "a mode")
                              .text("label", &Demo::label, "a label")
                              .real("low", &Demo::low, "", between(0, 1), "a low bound...")
                              .real("high", &Demo::high, "", between(0, 1), "...and a high one")
                              .rule([](const Demo& d) { return d.low < d.high; }, "need low < high");
    return t;
  }
};

Demo load(const std::string& text)
{
  return Demo::table().load(mrpt::config::CConfigFileMemory("[demo]\n" + text));
}

/** Loading `text` fails with a message holding `expected`. */
void expectError(const std::string& text, const std::string& expected)
{
  try
  {
    load(text);
    ADD_FAILURE() << "accepted: " << text;
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(ParamTable, LoadsEachKindAndKeepsTheDefaultsOfAbsentKeys)
{
  const Demo d = load("length = 1.25\nturn_DEG = 90\ncount = 7\nwindow = 12\non = no\nmode = fast\nlabel = front\n");
  EXPECT_EQ(d.length, 1.25);
  EXPECT_EQ(d.turn, mrpt::DEG2RAD(90.0));
  EXPECT_EQ(d.count, 7);
  EXPECT_EQ(d.window, 12u);
  EXPECT_FALSE(d.on);
  EXPECT_EQ(d.mode, Mode::Fast);
  EXPECT_EQ(d.label, "front");
  EXPECT_EQ(d.low, Demo().low);  // absent: the in-class default
  // Keys are matched as MRPT's reader matches them, whatever their case.
  EXPECT_EQ(load("LENGTH = 2\n").length, 2.0);
}

TEST(ParamTable, AnUnknownKeyIsAnErrorNamingTheValidOnes)
{
  expectError("lenght = 1\n", "unknown key 'lenght' in section [demo]; known keys: length, turn_DEG, count");
}

TEST(ParamTable, AValueNotOfItsKindOrOutOfRangeIsAnErrorNamingTheKey)
{
  expectError("length = abc\n", "[demo] length = 'abc' is not a number");
  expectError("length = 1 2\n", "[demo] length = '1 2' is not a number");
  expectError("length = nan\n", "is not a number");
  expectError("length =\n", "has no value");
  expectError("length = 0\n", "length must be > 0 m, got 0");
  expectError("length = inf\n", "length must be > 0 m");
  expectError("turn_DEG = 181\n", "turn_DEG must be in [0, 180] deg");
  expectError("count = 2.5\n", "[demo] count = '2.5' is not an integer");
  expectError("count = 1e3\n", "is not an integer");
  expectError("count = 99999999999999999999\n", "is not an integer");
  expectError("count = -1\n", "[demo] count = '-1' must be >= 0");
  expectError("window = -1\n", "[demo] window = '-1' must be >= 2");  // never wrapped to 2^64 - 1
  expectError("on = 0x10\n", "is not a boolean");
  expectError("mode = medium\n", "is not one of: slow, fast");
  expectError("on = true # note\n", "comments must be on a line of their own");
  expectError("low = 0.8\n", "need low < high");
}

TEST(ParamTable, TheEndOfARangeIsExactInTheFilesUnits)
{
  // 180 degrees is DEG2RAD(180) in the struct, and accepted whatever the rounding.
  EXPECT_EQ(load("turn_DEG = 180\n").turn, mrpt::DEG2RAD(180.0));
  EXPECT_EQ(load("turn_DEG = 0\n").turn, 0.0);
  Demo d;
  d.turn = mrpt::DEG2RAD(180.0) * (1 + 1e-15);
  EXPECT_THROW(Demo::table().check(d), std::invalid_argument);
}

TEST(ParamTable, ARangeSaysWhatItAccepts)
{
  EXPECT_TRUE(between(0, 1).contains(0));
  EXPECT_FALSE(above(0).contains(0));
  EXPECT_FALSE(anyNumber().contains(std::numeric_limits<double>::infinity()));
  const Range shape{-std::numeric_limits<double>::infinity(), 2, false, false};  // Barron's [-inf, 2]
  EXPECT_TRUE(shape.contains(-std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(shape.contains(std::nan("")));
  EXPECT_EQ(between(0, 1).describe(), "in [0, 1]");
  EXPECT_EQ(aboveUpTo(0, 10).describe(), "in (0, 10]");
  EXPECT_EQ(atLeast(1).describe(), ">= 1");
  EXPECT_EQ(above(0.5).describe(), "> 0.5");
  EXPECT_EQ(shape.describe(), "in [-inf, 2]");
  EXPECT_EQ(anyNumber().describe(), "a finite number");
}

TEST(ParamTable, NumbersAreWrittenShortAndReadBackExactly)
{
  EXPECT_EQ(shortestText(0.1), "0.1");
  EXPECT_EQ(shortestText(0.0005), "0.0005");
  EXPECT_EQ(shortestText(30), "30");
  EXPECT_EQ(shortestText(1e-12), "1e-12");
  EXPECT_EQ(shortestText(1e12), "1e12");
  EXPECT_EQ(shortestText(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(degreesText(mrpt::DEG2RAD(0.0057)), "0.0057");
  EXPECT_EQ(degreesText(mrpt::DEG2RAD(180.0)), "180");
  // Any double reads back from its text; an angle in radians that some number of degrees
  // gives, to the same radians.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> exponent(-20, 20), mantissa(-10, 10);
  for (int i = 0; i < 2000; i++)
  {
    const double v = mantissa(rng) * std::pow(10.0, exponent(rng));
    EXPECT_EQ(std::strtod(shortestText(v).c_str(), nullptr), v) << shortestText(v);
    const double radians = mrpt::DEG2RAD(v);
    EXPECT_EQ(mrpt::DEG2RAD(std::strtod(degreesText(radians).c_str(), nullptr)), radians) << degreesText(radians);
  }
}

TEST(ParamTable, TheWrittenSectionReadsBackAndShowsOneTier)
{
  Demo d;
  d.length = 0.3;
  d.turn = mrpt::DEG2RAD(45.0);
  d.mode = Mode::Fast;
  const std::string user = Demo::table().ini(d, Tier::User);
  EXPECT_EQ(user, "[demo]\n# A demo section.\n# [m] a length\nlength = 0.3\n");
  const std::string expert = Demo::table().ini(d, Tier::Expert);
  EXPECT_EQ(expert.find("length ="), std::string::npos);
  EXPECT_NE(expert.find("# [deg] a turn\nturn_DEG = 45\n"), std::string::npos);
  EXPECT_NE(expert.find("mode = fast\n"), std::string::npos);
  // Both tiers read back to the same values.
  const Demo back = Demo::table().load(mrpt::config::CConfigFileMemory(user + expert.substr(expert.find('\n') + 1)));
  EXPECT_EQ(Demo::table().ini(back, Tier::User), user);
  EXPECT_EQ(Demo::table().ini(back, Tier::Expert), expert);
  EXPECT_EQ(Demo::table().names(Tier::User), std::vector<std::string>{"length"});
  EXPECT_EQ(Demo::table().names().size(), 9u);
}

TEST(ParamTable, AFileWithEveryKeyRequiredNamesTheMissingOne)
{
  const mrpt::config::CConfigFileMemory partial("[demo]\nlength = 1\n");
  EXPECT_THROW(Demo::table().requireAll(partial), std::invalid_argument);
  try
  {
    Demo::table().requireAll(partial);
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_EQ(std::string(e.what()), "missing key [demo] turn_DEG");
  }
  const mrpt::config::CConfigFileMemory none("[other]\nx = 1\n");
  EXPECT_THROW(Demo::table().requireAll(none), std::invalid_argument);
}

// The option table: one registration gives the parser's rule and the description, so the
// two agree at every range end, included or not; every floating-point option refuses NaN and
// the infinities by the same rule.
#include "tools/option_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace ncube {
namespace {

// Parses `--x TEXT` with one registered option; true when CLI11 accepts it.
template <typename Register>
bool accepts(Register add, const std::string& text) {
  CLI::App app;
  OptionTable table(app);
  add(table);
  std::vector<std::string> args{text, "--x"};  // CLI11 takes the arguments in reverse
  try {
    app.parse(args);
    return true;
  } catch (const CLI::ParseError&) {
    return false;
  }
}

TEST(OptionTable, NumbersAreFiniteDecimalsInTheirRange) {
  double value = 0.5;
  const auto half_open = [&](OptionTable& t) {
    t.number("--x", value, {0.0, 1.0, false, true}, "a fraction above 0", "x");
  };
  for (const char* bad : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e999", "0x1p-2",
                          "", "0", "-0", "1.0000001", "abc", "1,5"})
    EXPECT_FALSE(accepts(half_open, bad)) << bad;
  for (const char* good : {"1", "1.0", ".5", "1e-300", "4.9e-324", "+0.25"})
    EXPECT_TRUE(accepts(half_open, good)) << good;
  ASSERT_TRUE(accepts(half_open, "0.125"));
}

TEST(OptionTable, NegativeZeroReadsAsZero) {
  double value = 1;
  const auto closed = [&](OptionTable& t) { t.number("--x", value, {0.0, 1.0}, "", "x"); };
  ASSERT_TRUE(accepts(closed, "-0"));
  EXPECT_EQ(value, 0.0);
  EXPECT_FALSE(std::signbit(value));  // -0.0 == 0.0: the sign is what the result file shows
  for (const char* zero : {"-0.0", "-0e5", "-1e-400"}) {
    value = 1;
    ASSERT_TRUE(accepts(closed, zero)) << zero;
    EXPECT_FALSE(std::signbit(value)) << zero;
  }
}

TEST(OptionTable, IntegersAreDecimalAndSquaresSquare) {
  int count = 4;
  const auto squares = [&](OptionTable& t) { t.square("--x", count, 1, 64, "", "x"); };
  for (const char* good : {"1", "4", "49", "64"}) EXPECT_TRUE(accepts(squares, good)) << good;
  for (const char* bad : {"0", "2", "63", "81", "-4", "016", "0x10", "4.0", "nan"})
    EXPECT_FALSE(accepts(squares, bad)) << bad;
}

TEST(OptionTable, DescribesWhatItParses) {
  CLI::App app;
  OptionTable table(app);
  double fraction = 0.25;
  int count = 3;
  std::string mode = "a";
  bool on = false;
  table.number("--fraction", fraction, {0.0, 1.0, false, true}, "a fraction", "fraction");
  table.integer("--count", count, -1, 10, "a count", "count");
  table.choice("--mode", mode, {"a", "b"}, "a mode", "mode");
  table.flag("--on", on, "a switch", "");
  const nlohmann::json described = table.describe();
  ASSERT_EQ(described.size(), 4u);
  EXPECT_EQ(described[0]["flag"], "--fraction");
  EXPECT_EQ(described[0]["kind"], "number");
  EXPECT_EQ(described[0]["default"], 0.25);
  EXPECT_EQ(described[0]["range"]["low_included"], false);
  EXPECT_EQ(described[0]["range"]["high"], 1.0);
  EXPECT_EQ(described[1]["range"]["low"], -1);
  EXPECT_TRUE(described[1]["range"]["low"].is_number_integer());
  EXPECT_EQ(described[2]["values"], nlohmann::json::array({"a", "b"}));
  EXPECT_FALSE(described[3].contains("field"));
}

}  // namespace
}  // namespace ncube

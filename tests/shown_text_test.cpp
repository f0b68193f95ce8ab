// Names echoed in messages (src/util/shown_text.h): control characters escaped, invalid UTF-8
// escaped, valid UTF-8 kept, long words and long messages cut, with the counts worked out here.
#include "util/shown_text.h"

#include <gtest/gtest.h>

namespace ncube {
namespace {

TEST(ShownText, KeepsPrintableText) {
  EXPECT_EQ(shown_text("scenes/scene2.json"), "scenes/scene2.json");
  EXPECT_EQ(shown_text("Stürzlinger & Wild — 1994"), "Stürzlinger & Wild — 1994");
  EXPECT_EQ(shown_text(""), "");
}

TEST(ShownText, EscapesControlCharacters) {
  EXPECT_EQ(shown_text("\x1b[31mred\x1b[0m"), "\\e[31mred\\e[0m");
  EXPECT_EQ(shown_text("a\nb\rc\td"), "a\\nb\\rc\\td");
  EXPECT_EQ(shown_text(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(shown_text("\x07\x7f"), "\\x07\\x7f");
  // C1: U+009B (CSI) as UTF-8, and a raw 0x9B byte (not UTF-8).
  EXPECT_EQ(shown_text("\xc2\x9b" "2J"), "\\u009b2J");
  EXPECT_EQ(shown_text("\x9b" "2J"), "\\x9b2J");
}

TEST(ShownText, EscapesBytesThatAreNotUtf8) {
  EXPECT_EQ(shown_text("\xff"), "\\xff");
  EXPECT_EQ(shown_text("a\xc3"), "a\\xc3");           // a sequence cut short
  EXPECT_EQ(shown_text("\xc0\xaf"), "\\xc0\\xaf");    // an overlong '/'
  EXPECT_EQ(shown_text("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
}

TEST(ShownText, CutsALongWordInTheMiddle) {
  const std::string name(100000, 'a');
  // 200 characters kept: 150 before, 50 after, 99,800 cut.
  const std::string expected = std::string(150, 'a') + "[... 99800 characters ...]" + std::string(50, 'a');
  EXPECT_EQ(shown_text(name), expected);
  EXPECT_EQ(shown_text(std::string(kMaxShownWord, 'b')), std::string(kMaxShownWord, 'b'));
  // A word of escapes counts its characters, not its bytes shown.
  const std::string shown = shown_text(std::string(1000, '\x1b'));
  EXPECT_EQ(shown.substr(0, 4), "\\e\\e");
  EXPECT_NE(shown.find("[... 800 characters ...]"), std::string::npos);
  EXPECT_EQ(shown.find('\x1b'), std::string::npos);
}

TEST(ShownText, CutsALongMessage) {
  std::string many;
  for (int i = 0; i < 50000; ++i) many += "a ";  // 100,000 characters, no long word
  const std::string shown = shown_text(many);
  // 1,800 characters kept (1,350 before, 450 after) around the marker.
  EXPECT_EQ(shown.substr(0, 1350) + "[... 98200 characters ...]" + shown.substr(shown.size() - 450),
            shown);
  EXPECT_EQ(shown.size(), 1800u + std::string("[... 98200 characters ...]").size());
}

TEST(ShownText, ShowingTwiceChangesNothing) {
  for (const std::string text : {std::string("\x1b[2J name\n"), std::string(300, 'x'),
                                 std::string("a\xff b")})
    EXPECT_EQ(shown_text(shown_text(text)), shown_text(text));
}

}  // namespace
}  // namespace ncube

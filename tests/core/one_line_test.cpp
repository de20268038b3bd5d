// Error messages as one line of valid UTF-8 (core/one_line.hpp): what the CLI prints and the
// Python module raises, whatever a message quotes.
#include "core/one_line.hpp"

#include <gtest/gtest.h>

namespace sansui {
namespace {

TEST(OneLine, NewlinesControlBytesAndBrokenUtf8BecomeVisibleText) {
  EXPECT_EQ(one_line("cannot read @\n: No such file\n\n"), "cannot read @ / : No such file");
  EXPECT_EQ(one_line("tab\there, bell\a"), "tab\\x09here, bell\\x07");
  // Valid characters pass: U+00E9, U+FFFD, U+1F600.
  EXPECT_EQ(one_line("caf\xc3\xa9 \xef\xbf\xbd \xf0\x9f\x98\x80"), "caf\xc3\xa9 \xef\xbf\xbd \xf0\x9f\x98\x80");
  // A character cut in two, an overlong form, a surrogate, a stray continuation byte.
  EXPECT_EQ(one_line("cut \xef\xbf"), "cut \\xef\\xbf");
  EXPECT_EQ(one_line("\xc0\xaf \xed\xa0\x80 \x80"), "\\xc0\\xaf \\xed\\xa0\\x80 \\x80");
}

TEST(OneLine, APrefixNeverCutsACharacter) {
  const std::string text = "ab\xef\xbf\xbd\xef\xbf\xbd";  // a, b, then two 3-byte characters
  EXPECT_EQ(utf8_prefix(text, 3), "ab");
  EXPECT_EQ(utf8_prefix(text, 5), "ab\xef\xbf\xbd");
  EXPECT_EQ(utf8_prefix(text, 6), "ab\xef\xbf\xbd");
  EXPECT_EQ(utf8_prefix(text, 100), text);
  EXPECT_EQ(one_line(utf8_prefix(text, 4)), "ab");
}

}  // namespace
}  // namespace sansui

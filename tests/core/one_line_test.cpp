// Error messages as one line of valid UTF-8 (core/one_line.hpp): what the CLI prints and the
// Python module raises, whatever a message quotes.
#include "core/one_line.hpp"

#include <string>

#include <gtest/gtest.h>

#include "core/error.hpp"

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

namespace sansui {
namespace {

TEST(OneLine, AnErrorKeepsItsWholeMessageWhenItQuotesANul) {
  // what() is a C string: a file name with a NUL byte in it once cut the message there.
  const std::string name("a\0b", 3);
  const InputError error("cannot read " + name + ": No such file or directory");
  EXPECT_EQ(std::string(error.what()), "cannot read a\\x00b: No such file or directory");
  EXPECT_EQ(one_line(error.what()), "cannot read a\\x00b: No such file or directory");
}

}  // namespace
}  // namespace sansui

// The TOML nesting limit: deep files are refused on their text, before toml++ parses them (which
// would overflow the stack), and every ordinary file passes with its true depth.
#include "core/toml_nesting.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "scene/recipe_file.hpp"
#include "tests/test_paths.hpp"

namespace sansui {
namespace {

std::string repeated(const std::string& part, int count, const std::string& separator) {
  std::string text;
  for (int i = 0; i < count; ++i) text += (i > 0 ? separator : "") + part;
  return text;
}

int depth(const std::string& text) {
  return toml_nesting_depth(text, 1000);
}

TEST(TomlNesting, CountsHeadersKeysArraysAndInlineTables) {
  EXPECT_EQ(depth("a = 1\n"), 1);
  EXPECT_EQ(depth("[world]\nsize = 33\n"), 2);
  EXPECT_EQ(depth("[render.fog]\ndensity = 1\n"), 3);
  EXPECT_EQ(depth("[[camera]]\nname = \"a\"\n"), 3);
  EXPECT_EQ(depth("a.b.c = 1\n"), 3);
  EXPECT_EQ(depth("\"a.b\".c = 1\n"), 2);  // a quoted part holds its dots
  EXPECT_EQ(depth("x = [[1, 2], [3]]\n"), 3);
  EXPECT_EQ(depth("x = { a = { b = 1 } }\n"), 3);
  EXPECT_EQ(depth("x = [\n  { a.b = [1] },\n]\n"), 5);
  EXPECT_EQ(depth("x = \"[[[[{{{{\"\ny = '''\n[[[[\n'''\nz = \"\"\"\n\\\"\"\" [[[\n\"\"\"\n"), 1);  // brackets in strings
  EXPECT_EQ(depth("# [[[[[[[[\nx = 1 # {{{{{{\n"), 1);
}

TEST(TomlNesting, EveryExampleSceneIsFarBelowTheLimit) {
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(sansui::test::source_dir) + "/examples")) {
    if (entry.path().extension() != ".toml") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    EXPECT_LE(depth(text.str()), 8) << entry.path();
    ++files;
  }
  EXPECT_GT(files, 5);
}

TEST(TomlNesting, DeepFilesAreRefusedOnOneLineNamingTheLimit) {
  const std::string cases[] = {
      "[render]\n" + repeated("a", 100000, ".") + " = 1\n",
      "[" + repeated("a", 100000, ".") + "]\nx = 1\n",
      "[[" + repeated("species", 100000, ".") + "]]\nx = 1\n",
      "x = " + repeated("{ a = ", 5000, "") + "1" + repeated(" }", 5000, "") + "\n",
      "x = " + std::string(100000, '[') + std::string(100000, ']') + "\n",
  };
  for (const std::string& text : cases) {
    try {
      check_toml_nesting(text, "deep.toml");
      ADD_FAILURE() << "accepted " << text.substr(0, 40);
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("deep.toml:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("more than 64 deep"), std::string::npos) << e.what();
    }
  }
}

TEST(TomlNesting, TheLimitItselfParses) {
  // 64 levels pass the check, and toml++ and the recipe reader take them (to the unknown key):
  // the limit is far from any stack trouble.
  const std::string text = "[render]\n" + repeated("a", max_toml_depth - 1, ".") + " = 1\n";
  EXPECT_NO_THROW(check_toml_nesting(text, "limit.toml"));
  try {
    (void)scene::parse_recipe_toml(text, "limit.toml", ".");
    ADD_FAILURE() << "an unknown key was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown key"), std::string::npos) << e.what();
  }
  EXPECT_THROW(check_toml_nesting(repeated("a", max_toml_depth + 1, ".") + " = 1\n", "over.toml"), InputError);
}

TEST(TomlNesting, CharactersToml33MishandlesAreRefusedWithTheirLine) {
  // toml++ 3.3's Unicode whitespace test is undefined behaviour for U+00A1..U+0499 (upstream
  // issue 295); it is asked about characters outside quotes and after backslashes in strings.
  const std::pair<std::string, std::string> cases[] = {
      {"a = 1\n\xc2\xa1\n", "deep.toml:2: not valid TOML: a character that is not ASCII outside quotes"},
      {"k\xc3\xa9y = 1\n", "deep.toml:1: not valid TOML: a character that is not ASCII outside quotes"},
      {"a = 1\xc3\xa9\n", "not ASCII outside quotes"},
      {"a = \"x\\\xc3\xa9\"\n", "a backslash before a character that is not ASCII"},
      {"a = \"\"\"x \\\n   \xc3\xa9\"\"\"\n", "deep.toml:2: not valid TOML: a line-ending backslash followed by"},
  };
  for (const auto& [text, message] : cases) {
    try {
      check_toml_nesting(text, "deep.toml");
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  // Anywhere TOML allows them, such characters pass: strings, comments, quoted keys.
  EXPECT_NO_THROW(check_toml_nesting(
      "# \xc2\xa1 caf\xc3\xa9\n\"caf\xc3\xa9\" = \"\xc2\xa1\"\nb = '\xc3\xa9'\nc = \"\"\"\n\xc3\xa9\\n\"\"\"\n", "ok.toml"));
}

}  // namespace
}  // namespace sansui

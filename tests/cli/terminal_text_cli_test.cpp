// Text from inputs reaches the terminal with its control bytes escaped (issue 15 item 8): a file
// name or a file's content holding ESC or CR, quoted in a message or a report line, must not
// move the cursor, recolour or overwrite the terminal, nor break the message's one line.
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

using ::testing::HasSubstr;

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

bool has_control_bytes(const std::string& text) {
  for (const char c : text)
    if (c == '\x1b' || c == '\r' || c == '\x07') return true;
  return false;
}

TEST(TerminalText, AFileNameWithEscapeAndCarriageReturnIsEscapedInTheMessage) {
  TempDir directory("terminal-name");
  const std::string name = "a\x1b[31m\rb.r32";  // both inputs: the first read may be either
  const CliResult r = run_cli({"compare", (directory / name).string(), (directory / name).string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(has_control_bytes(r.err)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("a\\x1b[31m\\x0db.r32"));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(TerminalText, ControlBytesInAFilesContentAreEscapedInTheMessage) {
  TempDir directory("terminal-content");
  write_text(directory / "seed.csv", "0,0\n10,0\n\x1b[2J\x1b[H,5\r\n0,10\n");
  const CliResult r = run_cli({"contour", (directory / "seed.csv").string(), "--contours", (directory / "c.geojson").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(has_control_bytes(r.err)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("\\x1b[2J"));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(TerminalText, AnOutputNameWithControlBytesIsRefusedWithTheNameEscaped) {
  // Output names may not hold control bytes at all (issue 30: the output plan): the refusal
  // quotes the name escaped, on one line, and writes nothing.
  TempDir directory("terminal-report");
  const auto out = directory / "t\x1b]0;title\x07.png";
  const CliResult r = run_cli({"terrain", "--size", "9", "-o", out.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(has_control_bytes(r.err)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("t\\x1b]0;title\\x07.png has a control character (\\x1b) in its name"));
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(files_in(directory.path()).empty());
}

}  // namespace
}  // namespace sansui::test

// Progress and notes on stderr as a user sees them: a bar on a terminal (run under a
// pseudo-terminal with script(1)), --progress=plain for logs, --quiet; the note for a 16-bit
// heightmap read without its sidecar.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/cli_runner.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui {
namespace {

std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++count;
  return count;
}

/// Runs `sansui ARGUMENTS` in `directory` with stdout and stderr on a pseudo-terminal; returns
/// what the terminal received.
test::CliResult run_on_terminal(const std::string& arguments, const std::filesystem::path& directory) {
  const std::string inner = "env -u DISPLAY -u WAYLAND_DISPLAY '" + std::string(sansui::test::cli_path) + "' " + arguments;
  const std::string command = "cd '" + directory.string() + "' && script -q -e -c \"" + inner + "\" /dev/null < /dev/null > '" +
                              (directory / "terminal.txt").string() + "' 2>&1";
  const int status = std::system(command.c_str());
  test::CliResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.err = test::read_text(directory / "terminal.txt");
  return result;
}

struct Redraw {
  std::string step;
  int percent = 0;
};

/// The bars drawn on the terminal, in order: each `\r` starts a redraw.
std::vector<Redraw> bars_in(const std::string& terminal) {
  static const std::regex bar(R"(^(.*\S) +\[[#-]+\] +(\d+)% .* left)");
  std::vector<Redraw> redraws;
  std::size_t start = 0;
  while (start < terminal.size()) {
    std::size_t end = terminal.find_first_of("\r\n", start);
    if (end == std::string::npos) end = terminal.size();
    std::smatch match;
    const std::string piece = terminal.substr(start, end - start);
    if (std::regex_search(piece, match, bar)) redraws.push_back({match[1].str(), std::stoi(match[2].str())});
    start = end + 1;
  }
  return redraws;
}

// Terrains eroded in a few steps; the long one runs its stream power step for about 5 s on a
// 2-core machine (the short one 1 s), long enough for a bar.
const std::string short_run = "terrain --size 1025 --seed 3 --erode --stage young --threads 2 -o t.r32";
const std::string long_run = "terrain --size 2049 --seed 3 --erode --stage young --threads 2 -o t.r32";

TEST(ProgressCli, BarOnATerminalIsMonotonicRateLimitedWithElapsedAndRemainingTime) {
  test::TempDir dir("progress-bar");
  const auto start = std::chrono::steady_clock::now();
  const test::CliResult r = run_on_terminal(long_run, dir.path());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<Redraw> redraws = bars_in(r.err);
  ASSERT_FALSE(redraws.empty()) << "no bar in " << seconds << " s: " << r.err;
  std::map<std::string, int> last;
  for (const Redraw& redraw : redraws) {
    auto [previous, first] = last.emplace(redraw.step, redraw.percent);
    if (!first) {
      EXPECT_GE(redraw.percent, previous->second) << redraw.step << " went back";
    }
    previous->second = std::max(previous->second, redraw.percent);
  }
  EXPECT_LE(static_cast<double>(redraws.size()), 12.0 * seconds + 2.0) << redraws.size() << " redraws in " << seconds << " s";
  EXPECT_NE(r.err.find(" left"), std::string::npos);
}

TEST(ProgressCli, PlainPrintsOneLinePerStepAndQuietNothing) {
  test::TempDir dir("progress-plain");
  const test::CliResult plain = test::run_cli_line("--progress=plain " + short_run, dir.path());
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.err.find('\r'), std::string::npos) << plain.err;
  static const std::regex line(R"(^sansui: (.+) (\d+)% in \S+ (s|min|h)$)");
  std::map<std::string, int> lines_per_step;
  std::size_t start = 0;
  while (start < plain.err.size()) {
    const std::size_t end = plain.err.find('\n', start);
    const std::string text = plain.err.substr(start, end - start);
    std::smatch match;
    if (std::regex_match(text, match, line)) ++lines_per_step[match[1].str()];
    start = end == std::string::npos ? plain.err.size() : end + 1;
  }
  ASSERT_FALSE(lines_per_step.empty()) << plain.err;
  for (const auto& [step, lines] : lines_per_step) EXPECT_EQ(lines, 1) << step;
  EXPECT_EQ(lines_per_step.count("terrain"), 1u) << plain.err;

  const test::CliResult quiet = run_on_terminal("--quiet " + short_run, dir.path());
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_TRUE(bars_in(quiet.err).empty()) << quiet.err;
  EXPECT_EQ(quiet.err.find('%'), std::string::npos) << quiet.err;
}

/// The steps of --progress=plain output, with their number of lines.
std::map<std::string, int> plain_steps(const std::string& err) {
  static const std::regex line(R"(^sansui: (.+) (\d+)% in \S+ (s|min|h)$)");
  std::map<std::string, int> steps;
  std::size_t start = 0;
  while (start < err.size()) {
    const std::size_t end = err.find('\n', start);
    const std::string text = err.substr(start, end - start);
    std::smatch match;
    if (std::regex_match(text, match, line)) ++steps[match[1].str()];
    start = end == std::string::npos ? err.size() : end + 1;
  }
  return steps;
}

TEST(ProgressCli, BenchSolidReportsEachTableAsAStep) {
  test::TempDir dir("progress-bench");
  const test::CliResult r =
      test::run_cli_line("--progress=plain bench solid --exp1-to 5 --exp2-from 4 --exp2-to 6 --memory-levels 5 --skip-targets", dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto steps = plain_steps(r.err);
  for (const char* step : {"experiment 1", "experiment 2", "memory"}) EXPECT_EQ(steps.count(step), 1u) << step << ": " << r.err;
  EXPECT_NE(r.out.find("Experiment 2"), std::string::npos);  // the tables still go to stdout
}

TEST(ProgressCli, SixteenBitHeightmapWithoutSidecarGetsOneNoteNamingWhatWasAssumed) {
  test::TempDir dir("progress-note");
  ASSERT_EQ(test::run_cli_line("terrain --size 65 --seed 7 -o hill.png", dir.path()).exit_code, 0);
  const std::string render = "render hill.png --view top --width 64 --samples 1 -o view.png";
  const test::CliResult with_sidecar = test::run_cli_line(render, dir.path());
  ASSERT_EQ(with_sidecar.exit_code, 0) << with_sidecar.err;
  EXPECT_EQ(with_sidecar.err.find("note"), std::string::npos) << with_sidecar.err;

  std::filesystem::remove(dir / "hill.png.json");
  const test::CliResult without = test::run_cli_line(render, dir.path());
  ASSERT_EQ(without.exit_code, 0) << without.err;
  EXPECT_EQ(count_of(without.err, "has no sidecar"), 1u) << without.err;
  EXPECT_EQ(count_of(without.err, "\n"), 1u) << without.err;
  EXPECT_NE(without.err.find("0 to 1000 m"), std::string::npos) << without.err;
  EXPECT_NE(without.err.find("cells of 1 m"), std::string::npos) << without.err;
  EXPECT_NE(without.err.find("[file] range"), std::string::npos) << without.err;
  EXPECT_NE(without.err.find("--range"), std::string::npos) << without.err;
  EXPECT_NE(without.err.find("--cell"), std::string::npos) << without.err;

  // Given on the command line, nothing is assumed; given only the cell, only the range is.
  const test::CliResult given = test::run_cli_line(render + " --range 0,500 --cell 10", dir.path());
  ASSERT_EQ(given.exit_code, 0) << given.err;
  EXPECT_EQ(given.err.find("note"), std::string::npos) << given.err;
  const test::CliResult cell_only = test::run_cli_line(render + " --cell 10", dir.path());
  EXPECT_EQ(count_of(cell_only.err, "has no sidecar"), 1u) << cell_only.err;
  EXPECT_EQ(cell_only.err.find("cells of"), std::string::npos) << cell_only.err;

  const test::CliResult quiet = test::run_cli_line("--quiet " + render, dir.path());
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_TRUE(quiet.err.empty()) << quiet.err;
}

}  // namespace
}  // namespace sansui

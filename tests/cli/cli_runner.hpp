// Runs the real `sansui` binary for end-to-end tests.
#pragma once

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "tests/test_paths.hpp"

namespace sansui::test {

struct CliResult {
  int exit_code = -1;
  std::string out;
  std::string err;

  std::string all() const { return out + err; }  ///< what a user sees on the terminal
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

/// Runs `sansui ARGUMENTS` through the shell (so ARGUMENTS is split and quoted as typed) with
/// stdin closed and no display, optionally in `working_directory`.
inline CliResult run_cli_line(const std::string& arguments, const std::filesystem::path& working_directory = {}) {
  const auto scratch = std::filesystem::temp_directory_path() / ("sansui-cli-" + std::to_string(::getpid()));
  std::filesystem::create_directories(scratch);
  // `leak_check` is put in env's list, so it reaches sansui and not the `cd` before it.
  const auto command = [&](const std::string& leak_check) {
    std::string line;
    if (!working_directory.empty()) line = "cd '" + working_directory.string() + "' && ";
    line += "env -u DISPLAY -u WAYLAND_DISPLAY " + leak_check + "'" + std::string(sansui::test::cli_path) + "' " + arguments;
    return line + " < /dev/null > '" + (scratch / "out").string() + "' 2> '" + (scratch / "err").string() + "'";
  };
  CliResult result;
  // In the sanitizer build, LeakSanitizer's tracer has crashed at exit of GL-rendering commands
  // ("Tracer caught signal 11 ... LeakSanitizer has encountered a fatal error", clang 14's
  // runtime), on every retry. scripts/test sets intercept_tls_get_addr=0, which removes the
  // cause it had; should it come back, the command is run once more with only the leak check
  // off. ASan and UBSan still watch that run; a real leak report is not a tracer crash, so it
  // ends the loop and is what the test sees.
  for (const char* leak_check : {"", "ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:detect_leaks=0\" "}) {
    const int status = std::system(command(leak_check).c_str());
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_text(scratch / "out");
    result.err = read_text(scratch / "err");
    if (result.err.find("LeakSanitizer has encountered a fatal error") == std::string::npos) break;
  }
  std::filesystem::remove_all(scratch);
  return result;
}

/// Runs `sansui ARGS...`, each argument passed as it is.
inline CliResult run_cli(const std::vector<std::string>& args) {
  std::string line;
  for (const auto& arg : args) line += " '" + arg + "'";
  return run_cli_line(line);
}

/// Files in a directory (names), to check that nothing was left behind.
inline std::vector<std::string> files_in(const std::filesystem::path& directory);

/// Bad input's contract: exit code 2, one line on stderr holding
/// `message`, and no file left in `output_dir`.
inline void expect_rejected(const CliResult& r, const std::string& message, const std::filesystem::path& output_dir) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(files_in(output_dir).empty()) << output_dir;
}

/// Files in a directory (names), to check that nothing was left behind.
inline std::vector<std::string> files_in(const std::filesystem::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) names.push_back(entry.path().filename().string());
  return names;
}

}  // namespace sansui::test

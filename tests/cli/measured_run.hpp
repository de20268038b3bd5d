// Runs the real `sansui` binary as a child and measures it: exit code, stderr, wall time and the
// child's own peak resident memory (wait4 reports it for that one child), for the limit and budget
// tests.
#pragma once

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>

#include "tests/cli/cli_runner.hpp"
#include "tests/test_paths.hpp"

extern char** environ;

namespace sansui::test {

/// A run of `sansui ARGS` with its own peak resident set (wait4 reports it for that one child).
struct MeasuredRun {
  int exit_code = -1;
  std::string err;
  long peak_rss_mb = 0;
  double seconds = 0.0;
};

inline MeasuredRun run_measured(const std::vector<std::string>& args, const std::filesystem::path& directory) {
  std::vector<std::string> argv_text{sansui::test::cli_path};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& text : argv_text) argv.push_back(text.data());
  argv.push_back(nullptr);
  const auto err_path = directory / "stderr.txt";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  // The child starts as this process (posix_spawn shares its memory until the exec), and Linux
  // counts that process's peak in the child's: lower this process's peak to what it holds now,
  // so that earlier tests of the same process do not show up as the child's memory.
  if (std::FILE* clear = std::fopen("/proc/self/clear_refs", "w")) std::fputs("5", clear), std::fclose(clear);
  const auto start = std::chrono::steady_clock::now();
  pid_t child = 0;
  MeasuredRun run;
  if (posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ) != 0) return run;
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  rusage usage{};
  ::wait4(child, &status, 0, &usage);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.peak_rss_mb = usage.ru_maxrss / 1024;  // Linux reports kilobytes
  run.err = read_text(err_path);
  std::filesystem::remove(err_path);
  return run;
}

}  // namespace sansui::test

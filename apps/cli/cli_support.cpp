#include "apps/cli/cli_support.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>

#include "scene/pipeline.hpp"

namespace sansui::cli {
namespace {

std::vector<std::string>& command_line() {
  static std::vector<std::string> words;
  return words;
}

}  // namespace

ProgressBar::ProgressBar() : start_(std::chrono::steady_clock::now()), terminal_(::isatty(STDERR_FILENO) == 1) {
  if (terminal_) context_.on_progress = [this](std::string_view stage, double fraction) { draw(stage, fraction); };
  context_.on_note = [this](std::string_view note) {
    clear();
    fmt::print(stderr, "sansui: note: {}\n", note);
  };
}

ProgressBar::~ProgressBar() {
  clear();
}

void ProgressBar::clear() {
  if (drawn_) std::fputs("\r\033[K", stderr);
  drawn_ = false;
}

void ProgressBar::draw(std::string_view stage, double fraction) {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (seconds < 1.0) return;  // short work stays silent
  constexpr int width = 30;
  const int filled = std::clamp(static_cast<int>(fraction * width + 0.5), 0, width);
  fmt::print(stderr, "\r{:<10} [{}{}] {:3.0f}% {:.1f} s", stage, std::string(static_cast<std::size_t>(filled), '#'),
             std::string(static_cast<std::size_t>(width - filled), '-'), 100.0 * fraction, seconds);
  std::fflush(stderr);
  drawn_ = true;
}

nlohmann::json run_provenance(const std::string& command) {
  return {{"program", "sansui"}, {"version", SANSUI_VERSION}, {"command", command}, {"command_line", command_line()}};
}

void set_command_line(int argc, char** argv) {
  command_line().assign(argv, argv + argc);
}

bool& verbose() {
  static bool on = false;
  return on;
}

void run_recipe_and_report(const scene::Recipe& recipe, const std::string& command) {
  scene::RunOptions options;
  options.provenance = run_provenance(command);
  options.verbose = verbose();
  scene::RunReport report;
  {
    ProgressBar progress;
    report = scene::run_recipe(recipe, options, progress.context());
  }
  for (const auto& line : report.lines) fmt::print("{}\n", line);
  if (options.verbose) {
    double total = 0.0;
    for (const auto& [stage, seconds] : report.seconds) total += seconds;
    for (const auto& [stage, seconds] : report.seconds) fmt::print("seconds: {:<10} {:7.3f}\n", stage, seconds);
    fmt::print("seconds: {:<10} {:7.3f}\n", "total", total);
  }
}

}  // namespace sansui::cli

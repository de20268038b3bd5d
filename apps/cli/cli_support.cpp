#include "apps/cli/cli_support.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>

#include <unistd.h>

#include <fmt/format.h>

#include "core/error.hpp"
#include "io/extension.hpp"

namespace sansui::cli {
namespace {

std::vector<std::string>& command_line() {
  static std::vector<std::string> words;
  return words;
}

}  // namespace

ProgressBar::ProgressBar() : start_(std::chrono::steady_clock::now()), terminal_(::isatty(STDERR_FILENO) == 1) {
  if (terminal_) context_.on_progress = [this](std::string_view stage, double fraction) { draw(stage, fraction); };
}

ProgressBar::~ProgressBar() {
  if (drawn_) std::fputs("\r\033[K", stderr);
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

std::pair<double, double> parse_pair(const std::string& text, const std::string& option) {
  const auto comma = text.find(',');
  auto number = [&](std::string_view part) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (error != std::errc() || end != part.data() + part.size() || part.empty())
      fail("{} '{}' is not allowed: give two numbers as A,B", option, text);
    return value;
  };
  if (comma == std::string::npos) fail("{} '{}' is not allowed: give two numbers as A,B", option, text);
  return {number(std::string_view(text).substr(0, comma)), number(std::string_view(text).substr(comma + 1))};
}

std::pair<int, int> parse_int_pair(const std::string& text, const std::string& option) {
  const auto [a, b] = parse_pair(text, option);
  if (a != static_cast<int>(a) || b != static_cast<int>(b)) fail("{} '{}' is not allowed: give two whole numbers as A,B", option, text);
  return {static_cast<int>(a), static_cast<int>(b)};
}

std::string extension_of(const std::filesystem::path& path) { return io::lower_extension(path); }

nlohmann::json run_provenance(const std::string& command) {
  return {{"program", "sansui"}, {"version", SANSUI_VERSION}, {"command", command}, {"command_line", command_line()}};
}

void set_command_line(int argc, char** argv) {
  command_line().assign(argv, argv + argc);
}

}  // namespace sansui::cli

// What every subcommand shares: the progress bar, option parsing helpers, output checks.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/context.hpp"

namespace sansui::cli {

/// A Context whose progress draws a bar on stderr, only when stderr is a terminal and the work
/// has run for more than a second. The bar is cleared when the object is destroyed.
class ProgressBar {
 public:
  ProgressBar();
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  const Context& context() const { return context_; }

 private:
  void draw(std::string_view stage, double fraction);
  Context context_;
  std::chrono::steady_clock::time_point start_;
  bool terminal_ = false;
  bool drawn_ = false;
};

/// Parses "A,B" into two numbers; throws InputError naming `option` if it is not that.
std::pair<double, double> parse_pair(const std::string& text, const std::string& option);
std::pair<int, int> parse_int_pair(const std::string& text, const std::string& option);

/// The extension of `path`, lower-case, with the dot (".png").
std::string extension_of(const std::filesystem::path& path);

/// Provenance shared by every output of one run: program, version, command line.
nlohmann::json run_provenance(const std::string& command);

/// The command line as typed, for provenance (set by main).
void set_command_line(int argc, char** argv);

}  // namespace sansui::cli

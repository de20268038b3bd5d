// What every subcommand shares: the progress bar, the provenance of a run, running a recipe.
#pragma once

#include <chrono>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/context.hpp"
#include "scene/recipe.hpp"

namespace sansui::cli {

/// A Context whose progress draws a bar on stderr, only when stderr is a terminal and the work
/// has run for more than a second, and whose notes go to stderr. The bar is cleared when the
/// object is destroyed.
class ProgressBar {
 public:
  ProgressBar();
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  const Context& context() const { return context_; }

 private:
  void draw(std::string_view stage, double fraction);
  void clear();
  Context context_;
  std::chrono::steady_clock::time_point start_;
  bool terminal_ = false;
  bool drawn_ = false;
};

/// Provenance shared by every output of one run: program, version, command, command line.
nlohmann::json run_provenance(const std::string& command);

/// The command line as typed, for provenance (set by main).
void set_command_line(int argc, char** argv);

/// Global options of main: --verbose.
bool& verbose();

/// Runs `recipe` with a progress bar, prints its report on stdout. Throws InputError.
void run_recipe_and_report(const scene::Recipe& recipe, const std::string& command);

}  // namespace sansui::cli

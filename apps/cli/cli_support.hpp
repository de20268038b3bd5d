// What every subcommand shares: the progress bar, the provenance of a run, running a recipe.
#pragma once

#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/context.hpp"
#include "core/tile_exchange.hpp"
#include "scene/recipe.hpp"

namespace sansui::cli {

/// How progress is shown (the global options --progress and --quiet).
enum class ProgressMode {
  automatic,  ///< a bar when stderr is a terminal, nothing otherwise
  bar,        ///< a bar on stderr even when it is not a terminal
  plain,      ///< one line per step on stderr when it ends, for logs and CI
  none,       ///< nothing
};

/// The global progress mode (set by main from --progress).
ProgressMode& progress_mode();

/// Global option --quiet: no progress and no notes on stderr (errors still are).
bool& quiet();

/// A Context whose progress is shown on stderr as progress_mode() says, and whose notes go to
/// stderr unless quiet(). The bar of a step appears once the step has run for a second; it never
/// goes backwards within a step, is redrawn at most 10 times a second and shows the step's
/// elapsed and estimated remaining time. The bar is cleared when the object is destroyed.
class ProgressBar {
 public:
  ProgressBar();
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;
  const Context& context() const { return context_; }

 private:
  using Clock = std::chrono::steady_clock;
  struct Step {
    std::string name;
    Clock::time_point start;
    double fraction = 0.0;
    bool ended = false;  ///< reached 1 (plain: its line was printed)
  };
  void progress(std::string_view stage, double fraction);
  void draw(const Step& step, Clock::time_point now);
  void end_line(const Step& step, Clock::time_point now);
  void clear();
  Context context_;
  ProgressMode mode_ = ProgressMode::none;
  std::vector<Step> steps_;
  Clock::time_point last_draw_{};
  Clock::time_point last_report_;
  bool drawn_ = false;
};

/// Provenance shared by every output of one run: program, version, command, command line.
nlohmann::json run_provenance(const std::string& command);

/// The command line as typed, for provenance (set by main).
void set_command_line(int argc, char** argv);

/// A message as one line on a terminal: input text quoted in it may hold control bytes (an escape
/// sequence, a carriage return, a newline), which are shown escaped instead of obeyed.
std::string terminal_line(std::string_view message);

/// Global option of main: --verbose.
bool& verbose();

/// Global option of main: --follow-symlinks (an output name that is a symbolic link is written
/// through it instead of being refused; scene::OutputRules::follow_symlinks).
bool& follow_symlinks();

/// The MPI ranks' exchange when the program runs under mpirun (main.cpp sets it), for tiled
/// worlds; null: one process.
TileExchange*& tile_exchange();

/// Runs `recipe` with a progress bar, prints its report on stdout. Throws InputError.
/// `cache_dir`: where a recipe graph keeps its nodes' results between runs (empty: nowhere).
void run_recipe_and_report(const scene::Recipe& recipe, const std::string& command, const std::filesystem::path& cache_dir = {});

}  // namespace sansui::cli

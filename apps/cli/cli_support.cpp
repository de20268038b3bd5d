#include "apps/cli/cli_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <unistd.h>

#include <fcntl.h>
#include <fmt/format.h>

#include "core/one_line.hpp"
#include "scene/pipeline.hpp"

namespace sansui::cli {
namespace {

std::vector<std::string>& command_line() {
  static std::vector<std::string> words;
  return words;
}

}  // namespace

ProgressMode& progress_mode() {
  static ProgressMode mode = ProgressMode::automatic;
  return mode;
}

bool& quiet() {
  static bool on = false;
  return on;
}

namespace {

std::string duration_text(double seconds) {
  if (seconds < 60.0) return fmt::format("{:.1f} s", seconds);
  const auto whole = static_cast<long long>(seconds + 0.5);
  if (whole < 3600) return fmt::format("{}:{:02} min", whole / 60, whole % 60);
  return fmt::format("{}:{:02}:{:02} h", whole / 3600, whole / 60 % 60, whole % 60);
}

/// Whether the user sees this process's stderr on a terminal: stderr itself, or, under mpirun
/// (which relays every rank's stderr through a pipe), the terminal mpirun was started from.
bool on_a_terminal(bool under_mpi) {
  if (::isatty(STDERR_FILENO) == 1) return true;
  if (!under_mpi) return false;
  const int terminal = ::open("/dev/tty", O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (terminal < 0) return false;
  ::close(terminal);
  return true;
}

}  // namespace

ProgressBar::ProgressBar() : last_report_(Clock::now()) {
  mode_ = quiet() ? ProgressMode::none : progress_mode();
  // Under mpirun every rank reports the whole world's progress (the tiled world's reports are
  // collective): rank 0 alone shows it, on a terminal as a bar and in a log as a line at least
  // every 10 s; the other ranks stay silent (their errors still print).
  const TileExchange* exchange = tile_exchange();
  const bool under_mpi = exchange != nullptr && exchange->ranks() > 1;
  if (under_mpi && exchange->rank() != 0) mode_ = ProgressMode::none;
  if (mode_ == ProgressMode::automatic)
    mode_ = on_a_terminal(under_mpi) ? ProgressMode::bar : under_mpi ? ProgressMode::plain : ProgressMode::none;
  if (mode_ != ProgressMode::none) context_.on_progress = [this](std::string_view stage, double fraction) { progress(stage, fraction); };
  if (!quiet())
    context_.on_note = [this](std::string_view note) {
      clear();
      // A note the library marks "warning: ..." is printed as the recipe file's warnings are.
      if (note.starts_with("warning: "))
        fmt::print(stderr, "sansui: {}\n", terminal_line(note));
      else
        fmt::print(stderr, "sansui: note: {}\n", terminal_line(note));
    };
}

ProgressBar::~ProgressBar() {
  clear();
  if (mode_ == ProgressMode::plain) {
    const auto now = Clock::now();
    for (const Step& step : steps_)
      if (!step.ended) end_line(step, now);
  }
}

void ProgressBar::clear() {
  if (drawn_) std::fputs("\r\033[K", stderr);
  drawn_ = false;
}

void ProgressBar::progress(std::string_view stage, double fraction) {
  const auto now = Clock::now();
  fraction = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
  auto step = std::find_if(steps_.begin(), steps_.end(), [&](const Step& s) { return s.name == stage; });
  // A step of the same name that had ended and starts again is a new step (a second erosion);
  // within a step the fraction never goes back (parallel workers report out of order).
  if (step != steps_.end() && step->ended && fraction < step->fraction) {
    steps_.erase(step);
    step = steps_.end();
  }
  if (step == steps_.end()) {
    // A step that reports only when done began when the one before it last reported.
    steps_.push_back(Step{std::string(stage), last_report_, fraction, false});
    step = steps_.end() - 1;
  }
  last_report_ = now;
  step->fraction = std::max(step->fraction, fraction);
  if (step->ended) return;
  if (step->fraction >= 1.0) {
    step->ended = true;
    clear();
    if (mode_ == ProgressMode::plain) end_line(*step, now);
    return;
  }
  if (mode_ == ProgressMode::plain) {
    // A log hears from a long step at least every 10 s, not only when it ends.
    if (now - step->start >= std::chrono::seconds(10) && now - last_draw_ >= std::chrono::seconds(10)) {
      const double seconds = std::chrono::duration<double>(now - step->start).count();
      fmt::print(stderr, "sansui: {} {:.0f}% after {}, {}\n", step->name, std::floor(100.0 * step->fraction), duration_text(seconds),
                 step->fraction >= 0.01 ? fmt::format("about {} left", duration_text(seconds * (1.0 - step->fraction) / step->fraction))
                                        : std::string("time left not known yet"));
      std::fflush(stderr);
      last_draw_ = now;
    }
    return;
  }
  if (mode_ != ProgressMode::bar) return;
  if (now - step->start < std::chrono::seconds(1)) return;        // short steps stay silent
  if (now - last_draw_ < std::chrono::milliseconds(100)) return;  // at most 10 redraws a second
  draw(*step, now);
}

void ProgressBar::draw(const Step& step, Clock::time_point now) {
  const double seconds = std::chrono::duration<double>(now - step.start).count();
  constexpr int width = 30;
  const int filled = std::clamp(static_cast<int>(step.fraction * width), 0, width);
  const std::string left =
      step.fraction >= 0.01 ? fmt::format("{} left", duration_text(seconds * (1.0 - step.fraction) / step.fraction)) : "-- left";
  fmt::print(stderr, "\r{:<10} [{}{}] {:3.0f}% {}, {}\033[K", step.name, std::string(static_cast<std::size_t>(filled), '#'),
             std::string(static_cast<std::size_t>(width - filled), '-'), std::floor(100.0 * step.fraction), duration_text(seconds), left);
  std::fflush(stderr);
  drawn_ = true;
  last_draw_ = now;
}

void ProgressBar::end_line(const Step& step, Clock::time_point now) {
  const double seconds = std::chrono::duration<double>(now - step.start).count();
  fmt::print(stderr, "sansui: {} {:.0f}% in {}\n", step.name, std::floor(100.0 * step.fraction), duration_text(seconds));
  std::fflush(stderr);
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

bool& follow_symlinks() {
  static bool on = false;
  return on;
}

TileExchange*& tile_exchange() {
  static TileExchange* exchange = nullptr;
  return exchange;
}

void run_recipe_and_report(const scene::Recipe& recipe, const std::string& command, const std::filesystem::path& cache_dir) {
  scene::RunOptions options;
  options.cache_dir = cache_dir;
  options.provenance = run_provenance(command);
  options.verbose = verbose();
  options.exchange = tile_exchange();
  scene::RunReport report;
  {
    ProgressBar progress;
    report = scene::run_recipe(recipe, options, progress.context());
  }
  // Report lines name files, which may hold any bytes: escaped as messages are.
  // Under mpirun, rank 0 speaks for the run (tiled_world.cpp gathers what it says).
  const TileExchange* exchange = tile_exchange();
  if (exchange != nullptr && exchange->rank() != 0) return;
  for (const auto& line : report.lines) fmt::print("{}\n", terminal_line(line));
  if (options.verbose) {
    double total = 0.0;
    for (const auto& [stage, seconds] : report.seconds) total += seconds;
    for (const auto& [stage, seconds] : report.seconds) fmt::print("seconds: {:<10} {:7.3f}\n", stage, seconds);
    fmt::print("seconds: {:<10} {:7.3f}\n", "total", total);
  }
}

std::string terminal_line(std::string_view message) {
  return one_line(message);
}

}  // namespace sansui::cli

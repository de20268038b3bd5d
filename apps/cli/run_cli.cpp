// `sansui`'s command line as a function (run_cli.hpp): options fill a recipe (the library's params
// structs, through their parameter tables), the library runs it. Bad input ends with one line on
// stderr and exit 2.
#include "apps/cli/run_cli.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/cli/cli_support.hpp"
#include "apps/cli/commands.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "scene/recipe_file.hpp"

namespace sansui::cli {
namespace {

/// CLI11's help, with a flag's "no" form written plainly: "--reuse, --no-reuse", not
/// "--reuse,--no-reuse{false}".
class HelpFormatter : public CLI::Formatter {
 public:
  std::string make_option_name(const CLI::Option* option, bool positional) const override {
    std::string name = CLI::Formatter::make_option_name(option, positional);
    for (std::size_t at = name.find("{false}"); at != std::string::npos; at = name.find("{false}")) name.erase(at, 7);
    return name;
  }
};

/// The line of a failed command: printed, or kept for main() (deferred_error()).
void print_error(const std::string& line) {
  if (std::string* kept = deferred_error())
    *kept = line;
  else
    fmt::print(stderr, "{}", line);
}

/// The deepest subcommand the parse reached (the app itself when none).
const CLI::App* deepest_command(const CLI::App& app) {
  const CLI::App* command = &app;
  for (bool deeper = true; deeper;) {
    deeper = false;
    for (const CLI::App* sub : command->get_subcommands()) {
      command = sub;
      deeper = true;
      break;
    }
  }
  return command;
}

/// "--hurts" is not an option: the nearest one of the command, as the TOML and Python paths
/// suggest keys; "terrian" is not a command: the nearest command.
std::string typo_hint(const CLI::App& app, const std::vector<std::string>& extras) {
  const CLI::App* command = deepest_command(app);
  for (const std::string& extra : extras) {
    if (extra.starts_with("--")) {
      const std::string name = extra.substr(2, extra.find('=') == std::string::npos ? std::string::npos : extra.find('=') - 2);
      std::vector<std::string> names;
      for (const CLI::App* level = command; level != nullptr; level = level->get_parent())
        for (const CLI::Option* option : level->get_options())
          for (const std::string& long_name : option->get_lnames()) names.push_back(long_name);
      if (const auto near = scene::nearest_key(name, names))
        return fmt::format("--{} is not an option of {}: did you mean --{}?", name, command == &app ? "sansui" : command->get_name(),
                           *near);
      return fmt::format("--{} is not an option of {} (sansui {} --help lists them)", name, command->get_name(), command->get_name());
    }
    if (command == &app && !extra.starts_with("-")) {
      std::vector<std::string> names;
      for (const CLI::App* sub : app.get_subcommands({})) names.push_back(sub->get_name());
      if (const auto near = scene::nearest_key(extra, names)) return fmt::format("'{}' is not a command: did you mean '{}'?", extra, *near);
      return fmt::format("'{}' is not a command: the commands are {}", extra, fmt::join(names, ", "));
    }
  }
  return "";
}

}  // namespace

std::string*& deferred_error() {
  static std::string* kept = nullptr;
  return kept;
}

int run_cli(int argc, char** argv, RecipeMode mode) {
  set_command_line(argc, argv);
  CLI::App app{"Sansui: procedural mountains, terrain, rock textures and scenery.", "sansui"};
  app.formatter(std::make_shared<HelpFormatter>());  // before the subcommands, which inherit it
  app.set_version_flag("--version", "sansui " SANSUI_VERSION);
  app.require_subcommand(1);
  app.fallthrough();
  int threads = 0;
  app.add_option("--threads", threads, "Worker threads; results are identical for any number. [Default: 0 = all cores]")
      ->check(CLI::Range(0, 1024));
  double max_memory_gb = 0.0;
  app.add_option("--max-memory", max_memory_gb,
                 "Most memory a stage may need, estimated from the sizes and counts in options and files (grids, pictures, "
                 "plants, trees, working arrays); larger ones are refused before any work (the message says the estimate and the "
                 "limit) [Units: GB] [Default: 3/4 of the physical memory]")
      ->check(CLI::PositiveNumber);
  std::unique_ptr<ThreadLimit> thread_limit;
  app.parse_complete_callback([&] {
    if (threads > 0) thread_limit = std::make_unique<ThreadLimit>(threads);
    if (max_memory_gb > 0.0) set_memory_limit_bytes(static_cast<std::size_t>(std::min(max_memory_gb * 1e9, 1e18)));
  });

  app.add_flag("-v,--verbose", verbose(), "Print the time of each step where a command measures them");
  app.add_flag("-q,--quiet", quiet(), "No progress and no notes on stderr (errors still are)");
  app.add_flag("--follow-symlinks", follow_symlinks(),
               "Write an output whose name is a symbolic link through the link, to its target (without it, such an output is "
               "refused: writing would replace the link with a file)");
  app.add_option("--progress",
                 "Progress on stderr: auto (a bar on a terminal), bar, plain (one line per step, for logs and CI), none "
                 "[Default: auto]")
      ->check(CLI::IsMember({"auto", "bar", "plain", "none"}))
      ->each([](const std::string& text) {
        progress_mode() = text == "bar"     ? ProgressMode::bar
                          : text == "plain" ? ProgressMode::plain
                          : text == "none"  ? ProgressMode::none
                                            : ProgressMode::automatic;
      })
      ->option_text("auto|bar|plain|none");

  add_recipe_commands(app, mode);
  if (mode == RecipeMode::run) {
    add_run_command(app);
    add_bench_command(app);
  }
  add_params_command(app);
  add_docs_commands(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // An unknown option or command: its nearest spelling instead of CLI11's "not expected".
    std::vector<std::string> extras = app.remaining(true);
    for (const CLI::App* sub = deepest_command(app); sub != &app && extras.empty(); sub = sub->get_parent()) extras = sub->remaining(true);
    if (const std::string hint = typo_hint(app, extras); !hint.empty()) {
      print_error(fmt::format("sansui: {}\n", terminal_line(hint)));
      return 2;
    }
    print_error(fmt::format("sansui: {} (run with --help for the options)\n", terminal_line(e.what())));
    return 2;
  } catch (const InputError& e) {
    print_error(fmt::format("sansui: {}\n", terminal_line(e.what())));
    return 2;
  } catch (const Cancelled&) {
    print_error("sansui: cancelled\n");
    return 130;
  } catch (const std::bad_alloc&) {
    print_error("sansui: out of memory: try a smaller size or tiles\n");
    return 3;
  } catch (const std::exception& e) {
    print_error(fmt::format("sansui: internal error: {}\n", terminal_line(e.what())));
    return 1;
  }
  return 0;
}

}  // namespace sansui::cli

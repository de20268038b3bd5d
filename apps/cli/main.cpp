// `sansui`: the command-line front end. A thin layer: options fill a recipe (the library's params
// structs, through their parameter tables), the library runs it. Bad input ends with one line on
// stderr and exit 2.
#include <cstdio>
#include <memory>

#include <fmt/format.h>
#include <tbb/global_control.h>

#include "apps/cli/cli_support.hpp"
#include "apps/cli/commands.hpp"
#include "core/error.hpp"
#include "core/worker_threads.hpp"
#include "io/atomic_file.hpp"

int main(int argc, char** argv) {
  const sansui::WorkerThreadsJoinedAtExit workers;
  sansui::io::remove_temporaries_on_signals();  // SIGINT, SIGTERM: no NAME.tmp-PID-N left behind
  sansui::cli::set_command_line(argc, argv);
  CLI::App app{"Sansui: procedural mountains, terrain, rock textures and scenery.", "sansui"};
  app.set_version_flag("--version", "sansui " SANSUI_VERSION);
  app.require_subcommand(1);
  app.fallthrough();
  int threads = 0;
  app.add_option("--threads", threads, "Worker threads; results are identical for any number. [Default: 0 = all cores]")
      ->check(CLI::Range(0, 1024));
  std::unique_ptr<tbb::global_control> thread_limit;
  app.parse_complete_callback([&] {
    if (threads > 0) thread_limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);
  });

  app.add_flag("-v,--verbose", sansui::cli::verbose(), "Print the time of each step where a command measures them");
  app.add_flag("-q,--quiet", sansui::cli::quiet(), "No progress and no notes on stderr (errors still are)");
  app.add_option("--progress",
                 "Progress on stderr: auto (a bar on a terminal), bar, plain (one line per step, for logs and CI), none "
                 "[Default: auto]")
      ->check(CLI::IsMember({"auto", "bar", "plain", "none"}))
      ->each([](const std::string& mode) {
        using sansui::cli::ProgressMode;
        sansui::cli::progress_mode() = mode == "bar"     ? ProgressMode::bar
                                       : mode == "plain" ? ProgressMode::plain
                                       : mode == "none"  ? ProgressMode::none
                                                         : ProgressMode::automatic;
      })
      ->option_text("auto|bar|plain|none");

  sansui::cli::add_recipe_commands(app);
  sansui::cli::add_run_command(app);
  sansui::cli::add_params_command(app);
  sansui::cli::add_bench_command(app);
  sansui::cli::add_docs_commands(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "sansui: {}\nRun with --help for the options.\n", e.what());
    return 2;
  } catch (const sansui::InputError& e) {
    fmt::print(stderr, "sansui: {}\n", e.what());
    return 2;
  } catch (const sansui::Cancelled&) {
    fmt::print(stderr, "sansui: cancelled\n");
    return 130;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "sansui: out of memory: try a smaller size or tiles\n");
    return 3;
  } catch (const std::exception& e) {
    fmt::print(stderr, "sansui: internal error: {}\n", e.what());
    return 1;
  }
  return 0;
}

// `sansui bench SUBSYSTEM`: benchmarks and the papers' experiments, printed as tables. The
// harnesses live in bench/harness/; this only binds their option tables.
#include <memory>

#include "apps/cli/bind_params.hpp"
#include "apps/cli/cli_support.hpp"
#include "apps/cli/commands.hpp"
#include "bench/harness/solid_experiments.hpp"

namespace sansui::cli {

void add_bench_command(CLI::App& app) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks and the papers' experiments, printed as tables.");
  bench->require_subcommand(1);
  auto options = std::make_shared<sansui::bench::SolidBenchOptions>();
  CLI::App* solid =
      bench->add_subcommand("solid", "The solid-texture paper's Experiments 1 and 2, its memory formulas, and the issue's targets.");
  bind_table(*solid, params::table_of<sansui::bench::SolidBenchOptions>(), *options, "", "Options");
  solid->add_option("--child", options->child, "")->group("");  // internal: one memory measurement
  solid->callback([options] {
    ProgressBar progress;  // the memory table's children report nothing: they run with --child
    sansui::bench::run_solid_experiments(*options, progress.context());
  });
}

}  // namespace sansui::cli

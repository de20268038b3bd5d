// `sansui params`: every parameter of every recipe section as Markdown (docs/params.md).
#include <fmt/format.h>

#include "apps/cli/commands.hpp"
#include "scene/params_doc.hpp"

namespace sansui::cli {

void add_params_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("params", "Print every parameter (section, key, type, unit, range, default, help) as Markdown.");
  command->callback([] { fmt::print("{}", scene::params_markdown()); });
}

}  // namespace sansui::cli

// `sansui man` and `sansui completion`: the manual page (roff) and a bash completion script,
// both made from the commands and options as built (so from the parameter tables, like
// docs/params.md). The build writes them to build/sansui.1 and build/sansui.bash; `cmake
// --install` installs them.
#include <fmt/format.h>

#include "apps/cli/bash_completion.hpp"
#include "apps/cli/commands.hpp"
#include "apps/cli/man_page.hpp"

namespace sansui::cli {

void add_docs_commands(CLI::App& app) {
  CLI::App* man = app.add_subcommand("man", "Print the manual page (roff; `sansui man > sansui.1`, then `man -l sansui.1`).");
  man->callback([&app] { fmt::print("{}", docs::man_page(app)); });
  CLI::App* completion = app.add_subcommand("completion", "Print a bash completion script (`source <(sansui completion)`).");
  completion->callback([&app] { fmt::print("{}", docs::bash_completion(app)); });
}

}  // namespace sansui::cli

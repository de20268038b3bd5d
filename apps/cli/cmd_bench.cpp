// Placeholder: the bench command arrives with its issue.
#include "apps/cli/commands.hpp"

namespace sansui::cli {

void add_bench_command(CLI::App&) {}

}  // namespace sansui::cli

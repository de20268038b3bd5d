// Placeholder: the compare command arrives with its issue.
#include "apps/cli/commands.hpp"

namespace sansui::cli {

void add_compare_command(CLI::App&) {}

}  // namespace sansui::cli

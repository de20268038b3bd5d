// Placeholder: the solid command arrives with its issue.
#include "apps/cli/commands.hpp"

namespace sansui::cli {

void add_solid_command(CLI::App&) {}

}  // namespace sansui::cli

// Placeholder: the subdivide command arrives with its issue.
#include "apps/cli/commands.hpp"

namespace sansui::cli {

void add_subdivide_command(CLI::App&) {}

}  // namespace sansui::cli

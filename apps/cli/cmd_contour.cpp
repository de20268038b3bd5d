// Placeholder: the contour command arrives with its issue.
#include "apps/cli/commands.hpp"

namespace sansui::cli {

void add_contour_command(CLI::App&) {}

}  // namespace sansui::cli

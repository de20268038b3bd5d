// Placeholder until the renderer lands.
#include "apps/cli/commands.hpp"

namespace sansui::cli {

void add_render_command(CLI::App&) {}

}  // namespace sansui::cli

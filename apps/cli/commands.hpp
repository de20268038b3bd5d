// The subcommands of `sansui`. Each file cmd_NAME.cpp adds one; main.cpp lists them.
#pragma once

#include <CLI/CLI.hpp>

namespace sansui::cli {

void add_terrain_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_contour_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_solid_command(CLI::App& app);
void add_subdivide_command(CLI::App& app);
void add_bench_command(CLI::App& app);

}  // namespace sansui::cli

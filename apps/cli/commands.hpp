// The subcommands of `sansui`. main.cpp lists them.
#pragma once

#include <CLI/CLI.hpp>

namespace sansui::cli {

void add_recipe_commands(CLI::App& app);  ///< terrain, render, contour, compare, solid, subdivide
void add_run_command(CLI::App& app);
void add_params_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_docs_commands(CLI::App& app);  ///< man, completion: made from the commands above

}  // namespace sansui::cli

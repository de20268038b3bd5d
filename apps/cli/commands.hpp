// The subcommands of `sansui`. main.cpp lists them.
#pragma once

#include <CLI/CLI.hpp>

#include "apps/cli/run_cli.hpp"

namespace sansui::cli {

/// terrain, render, contour, compare, solid, subdivide; `mode` says whether they run their recipe.
void add_recipe_commands(CLI::App& app, RecipeMode mode = RecipeMode::run);
void add_run_command(CLI::App& app);
void add_params_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_docs_commands(CLI::App& app);  ///< man, completion: made from the commands above

}  // namespace sansui::cli

// The whole `sansui` command line as a function, so that main() and the argv fuzz target
// (tests/fuzz) parse options with the same code.
#pragma once

#include <string>

namespace sansui::cli {

/// What a recipe command does once its options are parsed.
enum class RecipeMode {
  run,        ///< check, save (--save-recipe) and run the recipe: the command line
  check_only  ///< check the recipe and write nothing (the argv fuzz target); no `run` or `bench`
};

/// Parses `argv`, runs the command and returns the exit code: 0 done, 2 bad input (one line on
/// stderr), 3 out of memory, 130 cancelled, 1 internal error (a bug).
int run_cli(int argc, char** argv, RecipeMode mode = RecipeMode::run);

/// Where run_cli puts the one line of a failed command instead of printing it: set by main()
/// under mpirun, where one rank prints it for all when every rank failed alike. Null: printed.
std::string*& deferred_error();

}  // namespace sansui::cli

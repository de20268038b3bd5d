#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace sansui::cli::docs {

/// A bash completion script for `root` and its subcommands.
std::string bash_completion(const CLI::App& root);

}  // namespace sansui::cli::docs

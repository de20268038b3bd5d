#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace sansui::cli::docs {

/// The manual page of `root` and its subcommands, as roff.
std::string man_page(const CLI::App& root);

}  // namespace sansui::cli::docs

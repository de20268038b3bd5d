// What the manual page and the bash completion both read from the built command tree: which
// options are shown, which take a value, their names, the subcommands.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace sansui::cli::docs {

/// Options with no group are CLI11's hidden ones.
inline bool hidden(const CLI::Option* option) {
  return option->get_group().empty();
}

inline bool is_flag(const CLI::Option* option) {
  return option->nonpositional() && option->get_expected_max() == 0;
}

/// "-o, --out" (every name of the option, flags' "--no-" forms too).
inline std::vector<std::string> names_of(const CLI::Option* option) {
  std::vector<std::string> names;
  for (const auto& s : option->get_snames()) names.push_back("-" + s);
  for (const auto& l : option->get_lnames()) names.push_back("--" + l);
  return names;
}

inline std::vector<const CLI::App*> subcommands_of(const CLI::App* app) {
  return app->get_subcommands([](const CLI::App*) { return true; });
}

}  // namespace sansui::cli::docs

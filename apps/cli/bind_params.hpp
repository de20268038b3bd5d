// CLI options from parameter tables (core/params.hpp): one option per row, bound straight into
// the library struct, with help text made of the row's help, unit, range and default. A value is
// parsed and checked when the option is read, so a bad one fails naming the option.
#pragma once

#include <functional>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>

#include "core/params.hpp"

namespace sansui::cli {

/// "Hurst exponent H. [Range: > 0 and <= 1] [Default: 0.8]": a row's help for --help.
std::string option_help(const params::ParamInfo& row, const params::Value& default_value);

/// What --help shows after an option's name: INT, NUMBER, NUMBERS (N,N,...), FILE, TEXT, or
/// the choices (auto|bar|plain) when they are few.
std::string type_name(const params::ParamInfo& row);

/// The option names of a row: "--" + prefix + its flag, then its aliases ("--x,--alias").
std::string option_names(const params::ParamInfo& row, std::string_view flag_prefix);

/// Adds an option for `row` that writes into `target`. Flags (true/false rows) become
/// "--name" and "--no-name".
template <class S>
CLI::Option* bind_row(CLI::App& app, const params::Param<S>& row, S& target, std::string_view flag_prefix, const std::string& group) {
  const std::string names = option_names(row, flag_prefix);
  const std::string help = option_help(row, row.get(target));
  const std::string shown = "--" + std::string(flag_prefix) + row.flag;
  CLI::Option* option = nullptr;
  if (row.kind == params::Kind::flag) {
    const std::string flags = names + ",!--no-" + std::string(flag_prefix) + row.flag;
    option = app.add_flag_function(
        flags, [&row, &target](std::int64_t count) { row.set(target, count > 0); }, help);
  } else {
    option = app.add_option_function<std::string>(
        names,
        [&row, &target, shown](const std::string& text) {
          const params::Value value = params::parse_text(row, text, shown);
          params::require_allowed(row, value, shown);
          row.set(target, value);
        },
        help);
  }
  option->group(group);
  if (row.kind != params::Kind::flag) option->type_name(type_name(row));
  return option;
}

/// Binds every exposed, current row of `table` that `wanted` accepts (a superseded row is read
/// from older files only: the command line makes recipes of the current version).
template <class S>
void bind_table(CLI::App& app, const params::Table<S>& table, S& target, std::string_view flag_prefix, const std::string& group,
                const std::function<bool(const params::Param<S>&)>& wanted = {}) {
  for (const auto& row : table.rows)
    if (row.exposed && row.superseded_in == 0 && (!wanted || wanted(row))) bind_row(app, row, target, flag_prefix, group);
}

}  // namespace sansui::cli

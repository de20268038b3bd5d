#include "apps/cli/bind_params.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace sansui::cli {

std::string option_help(const params::ParamInfo& row, const params::Value& default_value) {
  std::string help = row.help;
  if (!row.unit.empty()) help += fmt::format(" [Units: {}]", row.unit);
  const std::string allowed = params::allowed_text(row);
  if (!allowed.empty() && row.kind != params::Kind::choice) help += fmt::format(" [Range: {}]", allowed);
  if (row.kind == params::Kind::choice) help += fmt::format(" [{}]", allowed);
  help += fmt::format(" [Default: {}]", params::default_text(row, default_value));
  return help;
}

std::string type_name(const params::ParamInfo& row) {
  switch (row.kind) {
    case params::Kind::integer:
      return "INT";
    case params::Kind::real:
      return "NUMBER";
    case params::Kind::reals:
      return "N,N...";
    case params::Kind::path:
      return "FILE";
    case params::Kind::choice:
      if (row.limits.choices.size() <= 6) return fmt::format("{}", fmt::join(row.limits.choices, "|"));
      return "CHOICE";
    default:
      return "TEXT";
  }
}

std::string option_names(const params::ParamInfo& row, std::string_view flag_prefix) {
  std::string names = "--" + std::string(flag_prefix) + row.flag;
  for (const auto& alias : row.aliases) names += "," + alias;
  return names;
}

}  // namespace sansui::cli

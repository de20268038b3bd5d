#include "core/params.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"

namespace sansui::params {
namespace {

std::string bounds_text(const Limits& limits) {
  const auto& [min, max] = std::pair{limits.min, limits.max};
  if (min && max && !limits.min_exclusive && !limits.max_exclusive)
    return fmt::format("between {} and {}", format_number(*min), format_number(*max));
  std::string low = min ? fmt::format("{} {}", limits.min_exclusive ? ">" : ">=", format_number(*min)) : "";
  std::string high = max ? fmt::format("{} {}", limits.max_exclusive ? "<" : "<=", format_number(*max)) : "";
  if (!low.empty() && !high.empty()) return low + " and " + high;
  return low + high;
}

/// A bound of a whole-number type: "2147483647", or "2^63 - 1" for the 64-bit ends.
std::string whole_bound(double v) {
  if (v >= 9.2e18) return "2^63 - 1";
  if (v <= -9.2e18) return "-2^63";
  return fmt::format("{}", static_cast<long long>(v));
}

bool within(const Limits& limits, double v) {
  if (limits.min && (limits.min_exclusive ? !(v > *limits.min) : !(v >= *limits.min))) return false;
  if (limits.max && (limits.max_exclusive ? !(v < *limits.max) : !(v <= *limits.max))) return false;
  if (limits.type_min && v < *limits.type_min) return false;
  if (limits.type_max && v > *limits.type_max) return false;
  return true;
}

std::string count_text(const Limits& limits) {
  const std::string what = limits.whole ? "whole numbers" : "numbers";
  if (limits.min_count == limits.max_count) return fmt::format("{} {}", limits.min_count, what);
  if (limits.max_count >= (1u << 20))
    return limits.min_count == 0 ? fmt::format("a list of at most {} {}", limits.max_count, what)
                                 : fmt::format("{} to {} {}", limits.min_count, limits.max_count, what);
  return fmt::format("{} to {} {}", limits.min_count, limits.max_count, what);
}

std::string kind_mismatch(const ParamInfo& row) {
  switch (row.kind) {
    case Kind::flag:
      return "true or false";
    case Kind::integer:
      return "a whole number";
    case Kind::real:
      return "a number";
    case Kind::text:
      return "text";
    case Kind::path:
      return "a file name";
    case Kind::choice:
      return allowed_text(row);
    case Kind::reals:
      return allowed_text(row);
  }
  return "?";
}

bool kind_matches(const ParamInfo& row, const Value& value) {
  switch (row.kind) {
    case Kind::flag:
      return std::holds_alternative<bool>(value);
    case Kind::integer:
      return std::holds_alternative<std::int64_t>(value);
    case Kind::real:
      return std::holds_alternative<double>(value);
    case Kind::text:
    case Kind::choice:
    case Kind::path:
      return std::holds_alternative<std::string>(value);
    case Kind::reals:
      return std::holds_alternative<std::vector<double>>(value);
  }
  return false;
}

double parse_number(std::string_view text, bool& ok) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  ok = !text.empty() && error == std::errc() && end == text.data() + text.size();
  return value;
}

}  // namespace

namespace detail {

std::string flag_of(std::string_view key) {
  std::string flag(key);
  for (char& c : flag)
    if (c == '_' || c == '.') c = '-';
  return flag;
}

}  // namespace detail

double float_as_written(float v) {
  if (!std::isfinite(v)) return static_cast<double>(v);
  const std::string text = fmt::format("{}", v);  // the shortest text that reads back to v
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

std::string format_number(double value) {
  if (value == 0.0) return "0";  // also -0
  return fmt::format("{}", value);
}

std::string format_value(const Value& value) {
  struct Visitor {
    std::string operator()(std::monostate) const { return ""; }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    std::string operator()(double v) const { return format_number(v); }
    std::string operator()(const std::string& v) const { return v; }
    std::string operator()(const std::vector<double>& v) const {
      std::string text;
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (i > 0) text += ',';
        text += format_number(v[i]);
      }
      return text;
    }
  };
  return std::visit(Visitor{}, value);
}

std::string_view kind_name(Kind kind) {
  switch (kind) {
    case Kind::flag:
      return "flag";
    case Kind::integer:
      return "integer";
    case Kind::real:
      return "real";
    case Kind::text:
      return "text";
    case Kind::choice:
      return "choice";
    case Kind::path:
      return "path";
    case Kind::reals:
      return "reals";
  }
  return "text";
}

std::string allowed_text(const ParamInfo& row) {
  std::string text;
  switch (row.kind) {
    case Kind::choice: {
      text = "one of ";
      for (std::size_t i = 0; i < row.limits.choices.size(); ++i) text += (i > 0 ? ", " : "") + row.limits.choices[i];
      return text;
    }
    case Kind::reals: {
      text = count_text(row.limits);
      const std::string bounds = bounds_text(row.limits);
      if (!bounds.empty()) text += ", each " + bounds + (row.unit.empty() ? "" : " " + row.unit);
      break;
    }
    case Kind::integer:
    case Kind::real:
      text = bounds_text(row.limits);
      if (!text.empty() && !row.unit.empty()) text += " " + row.unit;
      break;
    default:
      break;
  }
  if (!row.limits.rule_text.empty()) text = text.empty() ? row.limits.rule_text : text + ", " + row.limits.rule_text;
  return text;
}

std::string default_text(const ParamInfo& row, const Value& default_value) {
  if (std::holds_alternative<std::monostate>(default_value)) return row.unset_means.empty() ? "unset" : row.unset_means;
  std::string text = format_value(default_value);
  if (text.empty()) text = row.unset_means.empty() ? "none" : row.unset_means;
  return text;
}

std::string check(const ParamInfo& row, const Value& value) {
  if (std::holds_alternative<std::monostate>(value)) return row.optional ? "" : kind_mismatch(row);
  if (!kind_matches(row, value)) return kind_mismatch(row);
  const Limits& limits = row.limits;
  std::string problem;
  switch (row.kind) {
    case Kind::integer: {
      const double v = static_cast<double>(std::get<std::int64_t>(value));
      Limits type_only;
      type_only.type_min = limits.type_min, type_only.type_max = limits.type_max;
      // Outside the type (-1 for an unsigned field) or the field's range: the field's own range
      // if it has one (it lies inside the type's and is what the user may give), else the type's.
      if (!within(type_only, v) || !within(limits, v))
        problem = limits.min || limits.max ? allowed_text(row)
                                           : fmt::format("a whole number between {} and {}", whole_bound(limits.type_min.value_or(-9.3e18)),
                                                         whole_bound(limits.type_max.value_or(9.3e18)));
      break;
    }
    case Kind::real: {
      const double v = std::get<double>(value);
      if (!std::isfinite(v) || !within(limits, v)) {
        const std::string allowed = allowed_text(row);
        problem = allowed.empty() ? "a finite number" : allowed;
      }
      break;
    }
    case Kind::choice: {
      const auto& name = std::get<std::string>(value);
      if (std::find(limits.choices.begin(), limits.choices.end(), name) == limits.choices.end()) problem = allowed_text(row);
      break;
    }
    case Kind::reals: {
      const auto& numbers = std::get<std::vector<double>>(value);
      bool ok = numbers.size() >= limits.min_count && numbers.size() <= limits.max_count, finite = true;
      for (double v : numbers) {
        finite = finite && std::isfinite(v);
        ok = ok && std::isfinite(v) && within(limits, v) && (!limits.whole || v == std::floor(v));
      }
      if (!ok) problem = allowed_text(row) + (finite ? "" : ", all finite");
      break;
    }
    default:
      break;
  }
  if (problem.empty() && limits.rule) problem = limits.rule(value);
  return problem;
}

namespace {

/// A value to quote in a message, its NUL bytes as \x00: what() is a C string, which a NUL would
/// cut short (the CLI and Python make the rest of the message one line).
std::string without_nul(std::string_view text) {
  std::string out;
  for (const char c : text) out += c == '\0' ? std::string_view("\\x00") : std::string_view(&c, 1);
  return out;
}

}  // namespace

void require_allowed(const ParamInfo& row, const Value& value, std::string_view name) {
  const std::string problem = check(row, value);
  if (problem.empty()) return;
  if (std::holds_alternative<std::monostate>(value)) fail("{} is missing: it must be {}", name, problem);
  std::string shown = without_nul(format_value(value));
  if (row.kind == Kind::text || row.kind == Kind::choice || row.kind == Kind::path) shown = "'" + shown + "'";
  fail("{} {} is not allowed: it must be {}", name, shown, problem);
}

Value parse_text(const ParamInfo& row, std::string_view text, std::string_view name) {
  auto refuse = [&](std::string_view allowed) -> Value { fail("{} '{}' is not allowed: it must be {}", name, without_nul(text), allowed); };
  switch (row.kind) {
    case Kind::flag:
      if (text == "true" || text == "yes" || text == "on" || text == "1") return true;
      if (text == "false" || text == "no" || text == "off" || text == "0") return false;
      return refuse("true or false");
    case Kind::integer: {
      std::string_view digits = text;
      if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
      std::int64_t value = 0;
      const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
      if (digits.empty() || error != std::errc() || end != digits.data() + digits.size()) {
        // Too many digits for 64 bits (18446744073709551615 for a seed), or no bounds of its own:
        // name the bounds of the field's type, so the message says what is allowed.
        const std::string allowed = allowed_text(row);
        if ((allowed.empty() || error == std::errc::result_out_of_range) && (row.limits.type_min || row.limits.type_max))
          return refuse(fmt::format("a whole number between {} and {}", whole_bound(row.limits.type_min.value_or(-9.3e18)),
                                    whole_bound(row.limits.type_max.value_or(9.3e18))));
        return refuse(allowed.empty() ? "a whole number" : "a whole number " + allowed);
      }
      return value;
    }
    case Kind::real: {
      bool ok = false;
      const double value = parse_number(text, ok);
      if (!ok) {
        const std::string allowed = allowed_text(row);
        return refuse(allowed.empty() ? "a number" : "a number " + allowed);
      }
      return value;
    }
    case Kind::text:
    case Kind::choice:
    case Kind::path:
      return std::string(text);
    case Kind::reals: {
      std::vector<double> numbers;
      std::size_t start = 0;
      while (start <= text.size() && !text.empty()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        bool ok = false;
        numbers.push_back(parse_number(text.substr(start, comma - start), ok));
        if (!ok) return refuse(allowed_text(row) + " separated by commas");
        start = comma + 1;
      }
      return numbers;
    }
  }
  return {};
}

}  // namespace sansui::params

#include "io/json_text.hpp"

#include <charconv>
#include <cmath>

#include "core/error.hpp"

namespace sansui::io {
namespace {

/// The deepest nesting of [ and { outside strings, stopping early once past `limit`.
int nesting_depth(std::string_view text, int limit) {
  int depth = 0, deepest = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
      if (deepest > limit) break;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return deepest;
}

}  // namespace

void check_json_nesting(std::string_view text, std::string_view source) {
  if (nesting_depth(text, max_json_depth) > max_json_depth)
    fail("{}: not valid JSON: arrays and objects nested more than {} deep", source, max_json_depth);
}

nlohmann::json parse_json(std::string_view text, std::string_view source) {
  check_json_nesting(text, source);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // a syntax error, or a number out of a double's range
    fail("{}: not valid JSON: {}", source, json_error_text(e));
  }
}

std::string string_member(const nlohmann::json& object, const char* key) {
  if (!object.is_object()) return {};
  const auto member = object.find(key);
  return member != object.end() && member->is_string() ? member->get<std::string>() : std::string();
}

std::optional<std::int64_t> whole_number_in(const nlohmann::json& value, std::int64_t low, std::int64_t high) {
  if (value.is_number_unsigned()) {
    const std::uint64_t n = value.get<std::uint64_t>();
    if (high < 0 || n > static_cast<std::uint64_t>(high) || (low > 0 && n < static_cast<std::uint64_t>(low))) return std::nullopt;
    return static_cast<std::int64_t>(n);
  }
  if (!value.is_number_integer()) return std::nullopt;
  const std::int64_t n = value.get<std::int64_t>();
  if (n < low || n > high) return std::nullopt;
  return n;
}

std::string_view json_error_text(const nlohmann::json::exception& e) {
  // nlohmann's messages start "[json.exception.parse_error.101] parse error at line 1, column 5: ..."
  std::string_view message = e.what();
  if (const auto end_of_id = message.find("] "); message.starts_with("[json.exception.") && end_of_id != std::string_view::npos)
    message.remove_prefix(end_of_id + 2);
  return message;
}

bool parse_json_number(std::string_view token, double& out) {
  // -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?, then only white space.
  std::size_t i = 0;
  const auto digit = [&](std::size_t k) { return k < token.size() && token[k] >= '0' && token[k] <= '9'; };
  const auto digits = [&] {
    const std::size_t first = i;
    while (digit(i)) ++i;
    return i > first;
  };
  if (i < token.size() && token[i] == '-') ++i;
  if (i < token.size() && token[i] == '0') {
    ++i;
  } else if (!digits()) {
    return false;
  }
  if (i < token.size() && token[i] == '.' && (++i, !digits())) return false;
  if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
    if (!digits()) return false;
  }
  for (std::size_t k = i; k < token.size(); ++k)
    if (token[k] != ' ' && token[k] != '\t' && token[k] != '\n' && token[k] != '\r') return false;
  double value = 0.0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + i, value);
  if (error != std::errc() || end != token.data() + i || !std::isfinite(value)) return false;
  out = value;
  return true;
}

std::string dump_json(const nlohmann::json& value, int indent) {
  return value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace sansui::io

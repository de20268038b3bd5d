// JSON from outside (GeoJSON seeds, sketches, contours, sidecars, plant lists): one parser with
// the limits every reader needs, so that no JSON file can crash or escape as an internal error.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace sansui::io {

/// The deepest nesting of arrays and objects accepted: GeoJSON needs 7, sidecars about 6; the
/// readers walk documents recursively, so a file of 100,000 '[' must be refused before parsing.
inline constexpr int max_json_depth = 64;

/// Parses `text` (the contents of `source`, named in messages). Throws InputError, one line:
/// "SOURCE: not valid JSON: ..." for a syntax error (with line and column), a number that does
/// not fit a double (-148.1e9997), or nesting deeper than max_json_depth.
nlohmann::json parse_json(std::string_view text, std::string_view source);

/// Throws the InputError parse_json would if `text` nests arrays and objects deeper than
/// max_json_depth: for JSON another library parses (tinygltf).
void check_json_nesting(std::string_view text, std::string_view source);

/// `object[key]` if `object` is an object holding a string there, else "": GeoJSON's "type"
/// members, read without the type_error that `value(key, "")` throws for a non-string.
std::string string_member(const nlohmann::json& object, const char* key);

/// `value` if it is a whole number from `low` to `high`, else nullopt: nlohmann's get<int>() (or
/// any narrower integer) of a fractional or out-of-range number is undefined behaviour.
std::optional<std::int64_t> whole_number_in(const nlohmann::json& value, std::int64_t low, std::int64_t high);

/// nlohmann's message without its "[json.exception.type_error.302] " prefix, for a one-line
/// message to a user about a document that parsed but does not hold what it should.
std::string_view json_error_text(const nlohmann::json::exception& e);

/// The number a JSON number token spells (trailing white space allowed), into `out`: true if
/// `token` is a JSON number whose value is a finite double, false otherwise (then leave it to a
/// parser's own reading, for its message or an underflow to zero). std::from_chars: correctly
/// rounded like strtod, and fast for the 17 to 20 digits gdal_contour writes, where simdjson's
/// own reading takes a slow path beyond 19 digits (7 % of a `sansui contour-dem` run).
bool parse_json_number(std::string_view token, double& out);

/// `value` as JSON text (`indent` as nlohmann's dump). Every JSON Sansui writes goes through
/// here: strings may hold file names, which are bytes, not always UTF-8; a byte that is not
/// UTF-8 becomes U+FFFD instead of an exception (which reached the user as an internal error).
std::string dump_json(const nlohmann::json& value, int indent = -1);

}  // namespace sansui::io

// What the streaming GeoJSON readers (simdjson On-Demand) share: reading a number, and checking
// a value they do not use all through, so that text that is not JSON is refused wherever it
// stands, as a parse into a tree would refuse it.
#pragma once

#include <simdjson.h>

#include "io/json_text.hpp"

namespace sansui::io::ondemand {

namespace od = simdjson::ondemand;

/// A number value: std::from_chars on its token (parse_json_number), else simdjson's reading.
inline double number_of(od::value& value) {
  double out = 0.0;
  if (parse_json_number(value.raw_json_token(), out)) return out;
  return value.get_double();
}

/// Checks a scalar (a value or a whole document that is a number, string, boolean or null).
template <class Value>
void check_scalar(Value& value) {
  switch (value.type()) {
    case od::json_type::number: {
      double ignored = 0.0;
      if (!parse_json_number(value.raw_json_token(), ignored)) (void)value.get_double().value();
      break;
    }
    case od::json_type::string:
      (void)value.get_string().value();
      break;
    case od::json_type::boolean:
      (void)value.get_bool().value();
      break;
    case od::json_type::null:
      if (!value.is_null()) throw simdjson::simdjson_error(simdjson::N_ATOM_ERROR);
      break;
    default:
      break;
  }
}

/// Checks every token of `value`, which stands `depth` arrays and objects deep; deeper than
/// max_json_depth is refused, so the recursion is bounded whatever the text.
inline void skip(od::value value, int depth) {
  if (depth > max_json_depth) throw simdjson::simdjson_error(simdjson::DEPTH_ERROR);
  switch (value.type()) {
    case od::json_type::array:
      for (auto element : value.get_array()) skip(element.value(), depth + 1);
      break;
    case od::json_type::object:
      for (auto field : value.get_object()) {
        (void)field.unescaped_key().value();
        skip(field.value(), depth + 1);
      }
      break;
    default:
      check_scalar(value);
  }
}

/// skip() of a whole document, to its end: a number is read (consumed) by simdjson itself.
inline void skip_document(od::document& document) {
  const od::json_type type = document.type();
  if (type == od::json_type::array || type == od::json_type::object)
    skip(document.get_value(), 0);
  else if (type == od::json_type::number)
    (void)document.get_double().value();
  else
    check_scalar(document);
}

}  // namespace sansui::io::ondemand

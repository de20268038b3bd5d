// A TOML value as a parameter table's row takes it (core/params.hpp). Header-only: whoever
// includes it links toml++ (scene files, data/species.toml).
#pragma once

#include <optional>
#include <vector>

#include <toml++/toml.h>

#include "core/params.hpp"

namespace sansui::params {

/// The value of `node` in the kind `row` wants (an integer also serves as a real); nullopt when
/// the node has the wrong type.
inline std::optional<Value> value_of(const ParamInfo& row, const toml::node& node) {
  switch (row.kind) {
    case Kind::flag:
      if (const auto* v = node.as_boolean()) return v->get();
      break;
    case Kind::integer:
      if (const auto* v = node.as_integer()) return v->get();
      break;
    case Kind::real:
      if (const auto* v = node.as_floating_point()) return v->get();
      if (const auto* v = node.as_integer()) return static_cast<double>(v->get());
      break;
    case Kind::text:
    case Kind::choice:
    case Kind::path:
      if (const auto* v = node.as_string()) return v->get();
      break;
    case Kind::reals:
      if (const auto* array = node.as_array()) {
        std::vector<double> numbers;
        for (const toml::node& element : *array) {
          if (const auto* f = element.as_floating_point())
            numbers.push_back(f->get());
          else if (const auto* i = element.as_integer())
            numbers.push_back(static_cast<double>(i->get()));
          else
            return std::nullopt;
        }
        return numbers;
      }
      break;
  }
  return std::nullopt;
}

}  // namespace sansui::params

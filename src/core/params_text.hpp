// A params struct as one line of text, for cache keys: what a computation read from it.
#pragma once

#include <string>

#include "core/params.hpp"

namespace sansui::params {

/// Every row of `object` as "section{key=value;...}": two objects give the same text exactly
/// when every row has the same value (numbers in the fewest digits that read back the same).
template <class S>
std::string text_of(const S& object) {
  const Table<S>& table = table_of<S>();
  std::string text = table.section + "{";
  for (const auto& row : table.rows) text += row.key + "=" + format_value(row.get(object)) + ";";
  return text + "}";
}

}  // namespace sansui::params

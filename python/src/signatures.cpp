#include "signatures.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "scene/recipe.hpp"

namespace sansui::python {

bool has_function(const scene::NodeKind& kind) {
  return kind.group != "routing";
}

namespace {

const std::vector<std::string> world_call_keys = {"size", "cell", "sea_level", "crs", "origin"};

/// A value as Python source: True, 0.8, 'mature', [1.0, 2.0], None.
std::string python_literal(const params::Value& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>)
          return "None";
        else if constexpr (std::is_same_v<T, bool>)
          return v ? "True" : "False";
        else if constexpr (std::is_same_v<T, std::int64_t>)
          return fmt::format("{}", v);
        else if constexpr (std::is_same_v<T, double>) {
          std::string text = params::format_number(v);
          if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
          return text;
        } else if constexpr (std::is_same_v<T, std::string>) {
          std::string quoted = "'";
          for (char c : v) quoted += (c == '\'' || c == '\\') ? std::string("\\") + c : std::string(1, c);
          return quoted + "'";
        } else {
          std::string text = "[";
          for (std::size_t i = 0; i < v.size(); ++i) text += (i > 0 ? ", " : "") + params::format_number(v[i]);
          return text + "]";
        }
      },
      value);
}

const char* returns_text(scene::ValueType type) {
  return type == scene::ValueType::heights ? "heights in metres" : "a mask of 0..1";
}

std::string indent(const std::string& text, const std::string& prefix) {
  std::string out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
    out += (line.empty() ? "" : prefix + line) + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

}  // namespace

std::string python_type(const params::ParamInfo& row) {
  std::string type;
  switch (row.kind) {
    case params::Kind::flag:
      type = "bool";
      break;
    case params::Kind::integer:
      type = "int";
      break;
    case params::Kind::real:
      type = "float";
      break;
    case params::Kind::text:
      type = "str";
      break;
    case params::Kind::choice: {
      type = "Literal[";
      for (std::size_t i = 0; i < row.limits.choices.size(); ++i) type += fmt::format("{}\"{}\"", i > 0 ? ", " : "", row.limits.choices[i]);
      type += "]";
      break;
    }
    case params::Kind::path:
      type = "Union[str, os.PathLike[str]]";
      break;
    case params::Kind::reals:
      type = "Sequence[float]";
      break;
  }
  return row.optional ? "Optional[" + type + "]" : type;
}

std::string doc_line(const params::ParamInfo& row, const params::Value& default_value) {
  std::string line = fmt::format("{} ({}", row.key, python_type(row));
  if (!row.unit.empty()) line += fmt::format(", {}", row.unit);
  line += "): " + row.help;
  const std::string allowed = params::allowed_text(row);
  if (!allowed.empty() && row.kind != params::Kind::choice) line += fmt::format(". Allowed: {}", allowed);
  if (row.kind == params::Kind::choice) line += fmt::format(". One of {}", fmt::join(row.limits.choices, ", "));
  const std::string shown = params::default_text(row, default_value);
  if (!shown.empty()) line += fmt::format(". Default: {}", shown);
  return line + ".";
}

std::string positional_key(const scene::NodeKind& kind) {
  if (!kind.inputs.empty()) return {};
  if (kind.row("points") != nullptr) return "points";
  if (kind.name == "file" && kind.row("path") != nullptr) return "path";
  return {};
}

std::string positional_type(const scene::NodeKind& kind) {
  const std::string key = positional_key(kind);
  if (key == "points") return "Optional[ArrayLike]";
  const std::string type = python_type(*kind.row(key));
  return type.starts_with("Optional[") ? type : "Optional[" + type + "]";
}

std::vector<std::string> world_keys_of(const scene::NodeKind& kind) {
  std::vector<std::string> keys;
  for (const std::string& key : world_call_keys)
    if (kind.row(key) == nullptr) keys.push_back(key);
  return keys;
}

std::vector<std::string> call_keywords(const scene::NodeKind& kind) {
  std::vector<std::string> keys;
  for (const auto& row : kind.rows) keys.push_back(row.key);
  for (const auto& key : world_keys_of(kind)) keys.push_back(key);
  for (const auto& slot : kind.inputs) keys.push_back(slot.name);
  keys.emplace_back("world");
  keys.emplace_back("progress");
  return keys;
}

std::string node_docstring(const scene::NodeKind& kind) {
  std::string inputs;
  for (const auto& slot : kind.inputs) inputs += fmt::format("{}{}", slot.name, slot.optional ? "=None, " : ", ");
  const std::string first = positional_key(kind);
  if (!first.empty()) inputs = first + "=None, ";
  std::string text = fmt::format(
      "{}({}*, KEY=VALUE...) -> sansui.Grid\n\n{}.\n\nReturns {}: a sansui.Grid (a numpy float32 array of shape (rows, cols), row 0 "
      "north, that knows its world: cell, sea_level, crs, origin, x, y, transform), or an xarray.DataArray with x and y "
      "coordinates in metres and the CRS when an input is one or after sansui.set_arrays(\"xarray\").\n",
      kind.name, inputs, kind.help, returns_text(kind.output));
  if (!kind.inputs.empty()) {
    text +=
        "\nInputs (arrays of any rows x cols, the same for all, positional or by name; float32 C-contiguous arrays are read "
        "without a copy; a sansui.Grid or xarray.DataArray brings its world):\n";
    for (const auto& slot : kind.inputs)
      text += fmt::format("    {}: {}{}\n", slot.name, returns_text(slot.type), slot.optional ? " (optional)" : "");
  } else if (!first.empty()) {
    text += fmt::format("\nThe one positional argument, if given, is `{}`.\n", first);
  }
  text += "\nKeys:\n";
  const std::any defaults = kind.make();
  for (const auto& row : kind.rows) text += "    " + doc_line(row, kind.get(defaults, row.key)) + "\n";
  text += kind.inputs.empty() ? "\nWorld (default: sansui.World(); size is the samples per side):\n    world (sansui.World)\n"
                              : "\nWorld (default: the one the input arrays carry, else sansui.World() with a sansui.WorldWarning; size is "
                                "the arrays'):\n    world (sansui.World)\n";
  const auto& world_table = params::table_of<scene::WorldParams>();
  const scene::WorldParams world_defaults;
  for (const auto& key : world_keys_of(kind)) {
    const auto* row = world_table.find(key);
    text += "    " + doc_line(*row, row->get(world_defaults)) + "\n";
  }
  text += "\nprogress: a callable (stage: str, fraction: float), called as the work goes on; an exception it raises cancels.\n";
  return text;
}

std::string world_docstring() {
  std::string text = "World(**keys): the world a recipe and every node call work on (a recipe's [world] table).\n\nKeys:\n";
  const scene::WorldParams defaults;
  for (const auto& row : params::table_of<scene::WorldParams>().rows)
    if (row.exposed && row.superseded_in == 0) text += "    " + doc_line(row, row.get(defaults)) + "\n";
  return text;
}

std::string stubs_text() {
  std::string text = R"(# Type stubs of the sansui module, generated from Sansui's parameter tables by sansui_python_stubs.
# Do not edit: rebuild instead.
import os
from typing import Any, Callable, Dict, List, Literal, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

Array = npt.NDArray[np.float32]
ArrayLike = npt.ArrayLike
Progress = Optional[Callable[[str, float], object]]

__version__: str

)";
  // World
  text += "class World:\n" + indent("\"\"\"" + world_docstring() + "\"\"\"", "    ") + "    def __init__(self, *";
  const scene::WorldParams world_defaults;
  for (const auto& row : params::table_of<scene::WorldParams>().rows)
    if (row.exposed && row.superseded_in == 0)
      text += fmt::format(", {}: {} = {}", row.key, python_type(row), python_literal(row.get(world_defaults)));
  text += ") -> None: ...\n    def __getattr__(self, key: str) -> Any: ...\n    def to_dict(self) -> Dict[str, Any]: ...\n\n";
  text += grid_stubs();
  for (const scene::NodeKind& kind : scene::all_node_kinds()) {
    if (!has_function(kind)) continue;
    text += fmt::format("def {}(", kind.name);
    std::vector<std::string> parts;
    // Inputs are positional or by name (as the functions' inspect.signature says); so is
    // contour's points and file's path.
    for (const auto& slot : kind.inputs)
      parts.push_back(fmt::format("{}: {}", slot.name, slot.optional ? "Optional[ArrayLike] = None" : "ArrayLike"));
    const std::string first = positional_key(kind);
    if (!first.empty()) parts.push_back(fmt::format("{}: {} = None", first, positional_type(kind)));
    parts.emplace_back("*");
    const std::any defaults = kind.make();
    for (const auto& row : kind.rows)
      if (row.key != first)
        parts.push_back(fmt::format("{}: {} = {}", row.key, python_type(row), python_literal(kind.get(defaults, row.key))));
    for (const auto& key : world_keys_of(kind)) {
      const auto* row = params::table_of<scene::WorldParams>().find(key);
      const std::string type = python_type(*row);
      parts.push_back(fmt::format("{}: {} = None", key, type.starts_with("Optional[") ? type : "Optional[" + type + "]"));
    }
    parts.emplace_back("world: Optional[World] = None");
    parts.emplace_back("progress: Progress = None");
    text += fmt::format("{}) -> Grid:\n", fmt::join(parts, ", "));
    text += indent("\"\"\"" + node_docstring(kind) + "\"\"\"", "    ");
    text += "    ...\n\n";
  }
  text += extra_stubs();
  return text;
}

}  // namespace sansui::python

// What Python users read about the module, generated from the parameter tables: each node
// function's docstring and the type stubs (sansui/__init__.pyi) editors complete from. Plain C++
// (no Python): the stub generator (sansui_python_stubs) and the module share it.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/params.hpp"
#include "scene/node_kinds.hpp"

namespace sansui::python {

/// Whether a node kind is a Python function: not a routing kind (flow), whose heights carry their
/// routing only inside a graph; sansui.flow_routing() gives the routing itself as arrays.
bool has_function(const scene::NodeKind& kind);

/// The keyword arguments a node function takes: its table's keys, the world's, its inputs' names.
std::vector<std::string> call_keywords(const scene::NodeKind& kind);

/// The key a node function without input arrays also takes as its one positional argument:
/// contour's "points", file's "path"; empty for the others.
std::string positional_key(const scene::NodeKind& kind);

/// The Python type of that argument: "Optional[ArrayLike]" for points, the row's own otherwise.
std::string positional_type(const scene::NodeKind& kind);

/// The world's keys a node function takes (size, cell, sea_level, crs, origin), less any the
/// kind has as keys of its own.
std::vector<std::string> world_keys_of(const scene::NodeKind& kind);

/// The docstring of a node function: its call, what it returns, its inputs and every key.
std::string node_docstring(const scene::NodeKind& kind);

/// The docstring of sansui.World.
std::string world_docstring();

/// The Python type a row takes: "float", "int", "Optional[Sequence[float]]"...
std::string python_type(const params::ParamInfo& row);

/// A row's line in a docstring: "hurst (float): Hurst exponent H. Allowed: ... Default: 0.8."
std::string doc_line(const params::ParamInfo& row, const params::Value& default_value);

/// The stubs of what no table describes: Recipe, run, set_threads, the scenery functions
/// (api_stubs.cpp, written by hand beside the functions they describe).
std::string extra_stubs();

/// The stubs of sansui.Grid, grid(), set_arrays() and the water functions (api_stubs.cpp).
std::string grid_stubs();

/// The stubs of scenery.cpp's functions (scenery_stubs.cpp).
std::string scenery_stubs();

/// The docstrings of scenery.cpp's functions, by name: the module's and the stubs' (scenery_stubs.cpp).
const std::map<std::string, std::string>& scenery_docstrings();

/// The whole type stub file of the module.
std::string stubs_text();

}  // namespace sansui::python

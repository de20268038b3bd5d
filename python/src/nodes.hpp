// The node kinds of recipe graphs (scene/node_kinds.hpp) as Python functions, one per kind, and
// the world they run on: sansui.midpoint(size=1025, seed=7), sansui.erode(h, stage="mature"),
// sansui.blend(a, b, mask). Keyword arguments are the kind's parameter table; arrays come and go
// as numpy float32 (python/src/arrays.hpp).
#pragma once

#include <pybind11/pybind11.h>

#include "scene/node_kinds.hpp"
#include "scene/recipe.hpp"

namespace sansui::python {

namespace py = pybind11;

/// sansui.World: the recipe's [world] (scene::WorldParams), made from keyword arguments.
void add_world(py::module_& module);

/// One function per node kind.
void add_node_functions(py::module_& module);

/// The graph world of a [world]: its size, cell and sea level; relative file names from the
/// working directory.
scene::GraphWorld graph_world_of(const scene::WorldParams& world);

/// Sets the keys of a params object from keyword arguments (after the caller took its own).
void set_node_params(const scene::NodeKind& kind, std::any& params, const std::string& key, py::handle value);

}  // namespace sansui::python

// A scene's parts from Python, for those who build their own scenes (the Blender add-on):
// surface maps, water, plants and plant meshes, terrain meshes.
#pragma once

#include <pybind11/pybind11.h>

namespace sansui::python {

namespace py = pybind11;

void add_scenery(py::module_& module);

}  // namespace sansui::python

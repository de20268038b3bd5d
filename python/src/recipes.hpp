// Whole recipes from Python: sansui.Recipe (from a scene file, a dict shaped like one, or built
// node by node) and sansui.run(), which runs one as `sansui run` does and writes its outputs.
#pragma once

#include <pybind11/pybind11.h>

namespace sansui::python {

namespace py = pybind11;

void add_recipes(py::module_& module);

}  // namespace sansui::python

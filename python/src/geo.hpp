// Heightmap files with their own size, cell, origin and CRS, and CRSs described by PROJ, for the
// Python layer (sansui/_grids.py, sansui/_nodes.py): geo.cpp.
#pragma once

#include <pybind11/pybind11.h>

namespace sansui::python {

namespace py = pybind11;

/// _crs(text, what) and _read_heightmap(path, cell, progress).
void add_geo(py::module_& module);

}  // namespace sansui::python

// Flow routing, filled DEMs, drainage area, slope, rivers and lakes of numpy arrays, through the
// library's water/ functions, for sansui/_water.py: water.cpp.
#pragma once

#include <pybind11/pybind11.h>

namespace sansui::python {

namespace py = pybind11;

/// _flow_routing, _fill_depressions, _drainage_area, _slope, _surface_water, _flow_parameters.
void add_water(py::module_& module);

}  // namespace sansui::python

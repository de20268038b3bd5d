// numpy arrays and Sansui's grids, both ways. A grid handed to Python becomes a float32 array
// over the grid's own buffer (no copy): a capsule holding the grid is the array's base, so the
// buffer lives as long as any array or view of it. An array handed in is read in place when it is
// C-contiguous float32; any other array of real numbers is converted once (docs/python.md).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "core/grid.hpp"
#include "scene/node_kinds.hpp"

namespace sansui::python {

namespace py = pybind11;

/// What an array made by Sansui knows beyond its samples: the world it was made on and whether it
/// is heights or a mask. The Python layer (sansui/_grids.py) reads them once (grid_facts()) and
/// keeps them on the array it hands out, where copies keep them; here they serve the check that
/// a mask is not taken for heights.
struct GridFacts {
  scene::GraphWorld world;
  scene::ValueType type = scene::ValueType::heights;
  /// East and north of sample (0, 0), metres: (0, 0) on a world without an origin.
  std::array<double, 2> sample_origin{0.0, 0.0};
  /// The coordinate reference system's id or WKT; empty: none.
  std::string crs;
};

/// `grid` as a float32 array of shape (rows, cols), row 0 north, over the grid's own buffer.
py::array to_array(Grid<float> grid, const GridFacts& facts);

/// An array handed in, as a grid: borrowed from the array (kept alive by `keep`) or converted once.
struct InputGrid {
  Grid<float> grid;
  py::object keep;                 ///< the array the grid reads
  std::optional<GridFacts> facts;  ///< when the array is one Sansui made (or a full view of one)
  bool copied = false;             ///< true when the array had to be converted
};

/// Reads `object` (an array, or anything numpy.asarray takes) named `name` in messages: rows x
/// cols, any two sides (the algorithms take rectangles; only sources need a square world). Throws
/// TypeError (not real numbers) or ValueError (not 2-D, empty, too large, NaN or infinity).
InputGrid from_array(py::handle object, std::string_view name);

/// A capsule that keeps `owner` alive: the base of arrays over the buffers it holds, so they are
/// handed to Python without a copy and freed with the last array over them.
template <class T>
py::capsule keep_alive(std::shared_ptr<T> owner) {
  auto* held = new std::shared_ptr<T>(std::move(owner));
  return py::capsule(held, [](void* pointer) { delete static_cast<std::shared_ptr<T>*>(pointer); });
}

/// A C-ordered array of `shape` over `data`, which `base` keeps alive (no copy).
template <class T>
py::array array_over(const T* data, std::vector<py::ssize_t> shape, const py::capsule& base) {
  return py::array_t<T>(std::move(shape), data, base);
}

/// The facts of an array Sansui made, if `object` is one (the same buffer and shape).
std::optional<GridFacts> facts_of(py::handle object);

/// The facts of an array Sansui made as a dict for the Python layer (cell, sea_level, x0, y0,
/// crs, kind), or None for any other array.
py::object grid_facts(py::handle object);

/// The address of the samples of the grid behind an array Sansui made (its capsule's), for
/// tests of zero copy; none for other arrays.
std::optional<std::uintptr_t> held_grid_address(py::handle object);

}  // namespace sansui::python

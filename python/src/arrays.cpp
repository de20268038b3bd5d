#include "arrays.hpp"

#include <cmath>
#include <cstddef>
#include <utility>

#include <fmt/format.h>

namespace sansui::python {

namespace {

constexpr const char* capsule_name = "sansui.grid";

/// The grid and its facts, owned by the capsule that is the base of the array over them.
struct HeldGrid {
  Grid<float> grid;
  GridFacts facts;
};

std::string shape_text(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < array.ndim(); ++i) text += fmt::format("{}{}", i > 0 ? ", " : "", array.shape(i));
  return text + (array.ndim() == 1 ? ",)" : ")");
}

/// The first sample that is NaN or infinite, as (row, column).
std::optional<std::pair<std::size_t, std::size_t>> first_non_finite(const Grid<float>& grid) {
  const float* data = grid.data();
  const std::size_t n = grid.size();
  // x - x is 0 for finite x and NaN otherwise: one pass the compiler vectorises, then the exact place.
  float sum = 0.0f;
  for (std::size_t i = 0; i < n; ++i) sum += data[i] - data[i];
  if (sum == 0.0f) return std::nullopt;
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(data[i])) return std::pair{i / static_cast<std::size_t>(grid.width()), i % static_cast<std::size_t>(grid.width())};
  return std::nullopt;
}

}  // namespace

py::array to_array(Grid<float> grid, const GridFacts& facts) {
  auto* held = new HeldGrid{std::move(grid), facts};
  py::capsule owner(held, capsule_name,
                    [](PyObject* capsule) { delete static_cast<HeldGrid*>(PyCapsule_GetPointer(capsule, capsule_name)); });
  const auto rows = static_cast<py::ssize_t>(held->grid.height()), cols = static_cast<py::ssize_t>(held->grid.width());
  return py::array_t<float>({rows, cols}, {cols * static_cast<py::ssize_t>(sizeof(float)), static_cast<py::ssize_t>(sizeof(float))},
                            held->grid.data(), owner);
}

namespace {

/// The grid behind an array Sansui made, or of a view of one; null otherwise.
const HeldGrid* held_grid(py::handle object) {
  if (!py::isinstance<py::array>(object)) return nullptr;
  // Views keep their base array, which keeps the capsule: walk down to it.
  py::object base = object.attr("base");
  while (py::isinstance<py::array>(base)) base = base.attr("base");
  if (!PyCapsule_CheckExact(base.ptr()) || PyCapsule_GetName(base.ptr()) == nullptr ||
      std::string_view(PyCapsule_GetName(base.ptr())) != capsule_name)
    return nullptr;
  return static_cast<const HeldGrid*>(PyCapsule_GetPointer(base.ptr(), capsule_name));
}

}  // namespace

std::optional<std::uintptr_t> held_grid_address(py::handle object) {
  const HeldGrid* held = held_grid(object);
  if (held == nullptr) return std::nullopt;
  return reinterpret_cast<std::uintptr_t>(held->grid.data());
}

std::optional<GridFacts> facts_of(py::handle object) {
  const HeldGrid* held = held_grid(object);
  if (held == nullptr) return std::nullopt;
  const auto array = py::reinterpret_borrow<py::array>(object);
  // Only the whole grid as it was made: a slice or a transposed view is another grid.
  if (array.ndim() != 2 || array.data() != held->grid.data() || array.shape(0) != held->grid.height() ||
      array.shape(1) != held->grid.width() || array.strides(1) != static_cast<py::ssize_t>(sizeof(float)) ||
      array.strides(0) != static_cast<py::ssize_t>(sizeof(float)) * held->grid.width())
    return std::nullopt;
  return held->facts;
}

py::object grid_facts(py::handle object) {
  const std::optional<GridFacts> facts = facts_of(object);
  if (!facts) return py::none();
  py::dict out;
  out["cell"] = facts->world.cell_m;
  out["sea_level"] = facts->world.sea_level_m;
  out["x0"] = facts->sample_origin[0];
  out["y0"] = facts->sample_origin[1];
  out["crs"] = facts->crs.empty() ? py::object(py::none()) : py::object(py::str(facts->crs));
  out["kind"] = std::string(facts->type == scene::ValueType::heights ? "heights" : "mask");
  return out;
}

InputGrid from_array(py::handle object, std::string_view name) {
  InputGrid input;
  py::array array = py::isinstance<py::array>(object) ? py::reinterpret_borrow<py::array>(object)
                                                      : py::module_::import("numpy").attr("asarray")(object).cast<py::array>();
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
    throw py::type_error(fmt::format("{} must be an array of real numbers (float32 is read without a copy); its dtype is {}", name,
                                     py::str(array.dtype()).cast<std::string>()));
  if (array.ndim() != 2)
    throw py::value_error(fmt::format("{} must be a 2-D array (rows, cols); it is {}-D, shape {}", name, array.ndim(), shape_text(array)));
  if (array.shape(0) == 0 || array.shape(1) == 0) throw py::value_error(fmt::format("{} is empty: shape {}", name, shape_text(array)));
  for (int axis = 0; axis < 2; ++axis)
    if (array.shape(axis) > 1048577)
      throw py::value_error(
          fmt::format("{} has {} {}: at most 1048577 are allowed", name, array.shape(axis), axis == 0 ? "rows" : "columns"));
  // NPY_ARRAY_ALIGNED; dtype equality also refuses float32 of the other byte order.
  constexpr int aligned = 0x0100;
  const bool in_place =
      array.dtype().equal(py::dtype::of<float>()) && (array.flags() & py::array::c_style) != 0 && (array.flags() & aligned) != 0;
  if (!in_place) {
    array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
    if (!array) throw py::error_already_set();
    input.copied = true;
  }
  input.facts = facts_of(array);
  const auto rows = static_cast<int>(array.shape(0)), cols = static_cast<int>(array.shape(1));
  // The grid only reads: const_cast lets a borrowed Grid<float> stand for the caller's samples.
  input.grid = Grid<float>::borrowing(static_cast<float*>(const_cast<void*>(array.data())), cols, rows);
  if (input.facts) input.grid.cell_size_m = input.facts->world.cell_m;
  if (auto at = first_non_finite(input.grid))
    throw py::value_error(
        fmt::format("{} holds {} at row {}, column {}: every sample must be a finite number", name,
                    std::isnan(input.grid.data()[at->first * static_cast<std::size_t>(cols) + at->second]) ? "NaN" : "an infinity",
                    at->first, at->second));
  input.keep = std::move(array);
  return input;
}

}  // namespace sansui::python

// What the Python layer needs to know a grid's place: heightmap files read with their own size,
// cell, origin and CRS (sansui.file()), and coordinate reference systems checked and described by
// PROJ (io/crs.hpp). Both are the library's readers; nothing here computes.
#include "geo.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "calls.hpp"
#include "core/one_line.hpp"
#include "io/crs.hpp"
#include "io/heightmap_io.hpp"
#include "values.hpp"

namespace sansui::python {

namespace {

/// How a CRS is kept on a grid: its id ("EPSG:32654") when it has one, else its WKT.
std::string crs_text(const io::Crs& crs) {
  return crs.id.empty() ? crs.wkt : crs.id;
}

/// crs(text) -> dict | None: the CRS of `text` (EPSG:CODE, WKT...) as the outputs carry it:
/// text (its id, else WKT), label, name, wkt (WKT2), wkt1 (GDAL's WKT1), epsg (0: none). None for
/// Sansui's "local metres" (no CRS). ValueError for a CRS PROJ does not know or that is not in
/// metres (a geographic one).
py::object describe_crs(const std::string& text, const std::string& what) {
  if (text.empty()) return py::none();
  io::Crs crs;
  try {
    crs = io::parse_crs(text, what);
  } catch (const InputError& error) {
    throw py::value_error(one_line(error.what()));
  }
  if (io::is_local_metres(crs)) return py::none();
  if (crs.geographic || !crs.metric)
    throw py::value_error(
        fmt::format("{} {} is not allowed: it is in {}; Sansui's grids are in metres (reproject to a projected CRS first)", what,
                    crs.described(), crs.geographic ? "degrees" : crs.unit));
  py::dict out;
  out["text"] = crs_text(crs);
  out["label"] = crs.label();
  out["name"] = crs.name;
  out["wkt"] = crs.wkt;
  out["wkt1"] = io::crs_wkt1(crs);
  out["epsg"] = crs.epsg;
  return out;
}

/// _read_heightmap(path, cell, progress, range) -> (array, facts, notes): a heightmap file as it
/// is, with its own size (any rows x cols), cell, origin and CRS. `cell`: for a file that says
/// none; `range`: the metres of 16-bit 0 and 65535 (the file node's key), else the sidecar's;
/// None: facts["cell_assumed"] says whether the file said none (the Python layer picks the cell). notes: what the reader did on its own (a
/// range assumed, rectangular cells resampled to square ones, a CRS it could not carry).
py::tuple read_heightmap(const py::object& path_object, std::optional<double> cell_m, const py::object& progress,
                         std::optional<std::array<double, 2>> range_m) {
  const std::filesystem::path path = py::str(py::module_::import("os").attr("fspath")(path_object)).cast<std::string>();
  io::HeightmapReadOptions options;
  options.cell_size_m = cell_m;
  if (range_m) options.range = io::HeightRange{(*range_m)[0], (*range_m)[1]};
  io::HeightmapAssumptions assumed;
  std::vector<std::string> notes;
  std::string crs_note;
  std::optional<io::Crs> crs;
  Heightfield heights = run_released(progress, [&](const Context&) {
    Heightfield read = io::read_heightmap(path, options, &assumed);
    crs = io::read_heightmap_crs(path, &crs_note);
    return read;
  });
  const bool cell_assumed = assumed.cell_size;
  assumed.cell_size = false;  // the Python layer says that one itself, with the cell it took
  if (assumed.any()) notes.push_back(io::assumptions_note(path, assumed));
  for (const auto& note : assumed.notes) notes.push_back(note);
  if (!crs_note.empty()) notes.push_back(crs_note);
  py::dict facts;
  facts["cell"] = heights.cell_size_m;
  facts["x0"] = heights.origin_x_m;
  facts["y0"] = heights.origin_y_m == 0.0 ? 0.0 : -heights.origin_y_m;  // north of sample (0, 0); no -0
  facts["crs"] = crs && !io::is_local_metres(*crs) ? py::object(py::str(crs_text(*crs))) : py::object(py::none());
  facts["cell_assumed"] = cell_assumed;
  scene::GraphWorld world;
  world.width = heights.width(), world.height = heights.height();
  world.cell_m = heights.cell_size_m;
  return py::make_tuple(to_array(std::move(heights), GridFacts{world, scene::ValueType::heights, {0.0, 0.0}, {}}), facts, notes);
}

}  // namespace

void add_geo(py::module_& module) {
  module.def(
      "_crs", [](const std::string& text, const std::string& what) { return describe_crs(text, what); }, py::arg("text"),
      py::arg("what") = "crs");
  module.def("_read_heightmap", &read_heightmap, py::arg("path"), py::arg("cell"), py::arg("progress") = py::none(),
             py::arg("range") = py::none());
}

}  // namespace sansui::python

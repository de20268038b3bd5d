// The library's flow routing, depression filling, drainage area, slope, rivers and lakes
// (src/water, scene/water_geojson.hpp) over numpy arrays, for sansui/_water.py: the same
// functions the CLI's --rivers and --lakes outputs and the erosion use, so the same bytes.
// Arrays come back over the library's own buffers (no copy); the Python layer gives them their
// world.
#include "water.hpp"

#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "calls.hpp"
#include "io/crs.hpp"
#include "scene/water_geojson.hpp"
#include "signatures.hpp"
#include "values.hpp"
#include "water/flow.hpp"
#include "water/landform.hpp"
#include "water/priority_flood.hpp"
#include "water/surface_water.hpp"

namespace sansui::python {

namespace {

/// The world of a call, as the Python layer settled it.
struct Place {
  double cell_m = 10.0;
  double sea_level_m = 0.0;
  double x0_m = 0.0, y0_m = 0.0;  ///< east and north of sample (0, 0)
  std::string crs;                ///< id or WKT; empty: none
};

Place place_of(const py::dict& world) {
  Place place;
  place.cell_m = world["cell"].cast<double>();
  place.sea_level_m = world["sea_level"].cast<double>();
  place.x0_m = world["x0"].cast<double>();
  place.y0_m = world["y0"].cast<double>();
  if (world.contains("crs") && !world["crs"].is_none()) place.crs = world["crs"].cast<std::string>();
  return place;
}

/// The input as a heightfield on its place (cell size, and the origin the GeoJSON coordinates take).
InputGrid heights_of(py::handle array, const Place& place) {
  InputGrid input = from_array(array, "heights");
  input.grid.cell_size_m = place.cell_m;
  input.grid.origin_x_m = place.x0_m;
  input.grid.origin_y_m = place.y0_m == 0.0 ? 0.0 : -place.y0_m;
  return input;
}

/// An array over `grid`'s samples, which `base` keeps alive.
template <class T>
py::array grid_array(const Grid<T>& grid, const py::capsule& base) {
  return array_over(grid.data(), {static_cast<py::ssize_t>(grid.height()), static_cast<py::ssize_t>(grid.width())}, base);
}

const std::vector<std::string> world_call_keys = {"cell", "sea_level", "crs", "origin", "world", "progress"};

/// [flow]'s keys from keyword arguments (sea_level is the world's): TypeError naming `function`
/// for one it does not take.
water::FlowParams flow_params_of(std::string_view function, const py::dict& keys, const Place& place) {
  water::FlowParams params;
  const auto& table = params::table_of<water::FlowParams>();
  std::vector<std::string> known;
  for (const auto& row : table.rows)
    if (row.key != "sea_level") known.push_back(row.key);
  known.insert(known.end(), world_call_keys.begin(), world_call_keys.end());
  for (const auto& [key_object, value] : keys) {
    const auto key = key_object.cast<std::string>();
    const auto* row = table.find(key);
    if (row == nullptr || key == "sea_level") unknown_keyword(function, key, known);
    row->set(params, to_value(*row, value, key));
  }
  params.sea_level_m = place.sea_level_m;
  params.validate();
  return params;
}

/// The GeoJSON text with its crs member, as the CLI's outputs carry it (the grid's CRS, else
/// Sansui's local metres).
std::string with_crs(std::string text, const Place& place) {
  return io::with_geojson_crs(std::move(text), place.crs.empty() ? io::local_metres_crs() : io::parse_crs(place.crs, "crs"));
}

py::tuple flow_routing(const py::handle& array, const py::dict& world, const py::object& progress) {
  const Place place = place_of(world);
  InputGrid input = heights_of(array, place);
  std::vector<std::string> notes;
  struct Routed {
    water::FlowRouting flow;
    Grid<std::int32_t> basins;
  };
  auto routed = std::make_shared<Routed>(run_released(
      progress,
      [&](const Context& context) {
        Routed out{water::route_flow(input.grid, water::Outlets{place.sea_level_m}, context), {}};
        out.basins = water::basin_labels(out.flow.receiver, out.flow.stack);
        return out;
      },
      &notes));
  const py::capsule base = keep_alive(routed);
  py::dict out;
  out["filled"] = grid_array(routed->flow.surface, base);
  out["receivers"] = grid_array(routed->flow.receiver, base);
  out["stack"] = array_over(routed->flow.stack.data(), {static_cast<py::ssize_t>(routed->flow.stack.size())}, base);
  out["area"] = grid_array(routed->flow.area_m2, base);
  out["basins"] = grid_array(routed->basins, base);
  return py::make_tuple(out, notes);
}

py::tuple fill_depressions(const py::handle& array, const py::dict& world, bool epsilon, const py::object& progress) {
  const Place place = place_of(world);
  InputGrid input = heights_of(array, place);
  std::vector<std::string> notes;
  auto filled = std::make_shared<Heightfield>(run_released(
      progress,
      [&](const Context& context) {
        const water::Outlets outlets{place.sea_level_m};
        return epsilon ? water::fill_depressions_epsilon(input.grid, outlets, context)
                       : water::fill_depressions_with_lakes(input.grid, outlets, context).surface;
      },
      &notes));
  return py::make_tuple(grid_array(*filled, keep_alive(filled)), notes);
}

py::tuple drainage_area(const py::handle& array, const py::dict& world, const std::string& method, const py::dict& keys,
                        const py::object& progress) {
  const Place place = place_of(world);
  if (method != "d8" && method != "mfd")
    throw py::value_error(fmt::format("method '{}' is not allowed: it must be one of d8, mfd", method));
  const water::FlowParams params = flow_params_of("drainage_area", keys, place);
  InputGrid input = heights_of(array, place);
  std::vector<std::string> notes;
  auto area = std::make_shared<Grid<double>>(run_released(
      progress,
      [&](const Context& context) {
        const water::Outlets outlets{place.sea_level_m};
        if (method == "d8") return std::move(water::route_flow(input.grid, outlets, context).area_m2);
        // Freeman's routing needs a surface that drains everywhere.
        return water::mfd_drainage_area(water::fill_depressions_epsilon(input.grid, outlets, context), outlets, params.flow_exponent);
      },
      &notes));
  return py::make_tuple(grid_array(*area, keep_alive(area)), notes);
}

py::tuple slope(const py::handle& array, const py::dict& world, const py::object& progress) {
  const Place place = place_of(world);
  InputGrid input = heights_of(array, place);
  auto degrees = std::make_shared<Grid<float>>(run_released(progress, [&](const Context&) { return water::slope_degrees(input.grid); }));
  return py::make_tuple(grid_array(*degrees, keep_alive(degrees)), py::list());
}

py::tuple surface_water(const py::handle& array, const py::dict& world, const py::dict& keys, const py::object& progress) {
  const Place place = place_of(world);
  const water::FlowParams params = flow_params_of("surface_water", keys, place);
  InputGrid input = heights_of(array, place);
  std::vector<std::string> notes;
  struct Water {
    water::SurfaceWater water;
    std::string rivers, lakes;
  };
  auto made = std::make_shared<Water>(run_released(
      progress,
      [&](const Context& context) {
        Water out{water::surface_water(input.grid, params, context), {}, {}};
        // The outputs' GeoJSON writers, on the ground's plane (its cell and origin).
        out.rivers = with_crs(scene::rivers_to_geojson(out.water.rivers, input.grid), place);
        out.lakes = with_crs(scene::lakes_to_geojson(out.water.lakes, input.grid), place);
        return out;
      },
      &notes));
  const py::capsule base = keep_alive(made);
  py::dict out;
  out["surface"] = grid_array(made->water.surface, base);
  out["depth"] = grid_array(made->water.depth_m, base);
  out["wetness"] = grid_array(made->water.wetness, base);
  out["area"] = grid_array(made->water.area_m2, base);
  out["strahler"] = grid_array(made->water.rivers.strahler, base);
  out["lake"] = grid_array(made->water.lakes.lake, base);
  out["rivers"] = made->rivers;
  out["lakes"] = made->lakes;
  return py::make_tuple(out, notes);
}

/// The keys of [flow] a water function takes, as node_parameters() gives a node's.
py::list flow_parameters() {
  py::list out;
  const water::FlowParams defaults;
  for (const auto& row : params::table_of<water::FlowParams>().rows) {
    if (row.key == "sea_level" || !row.exposed) continue;
    const params::Value value = row.get(defaults);
    py::dict parameter;
    parameter["name"] = row.key;
    parameter["role"] = "key";
    parameter["default"] = to_python(value);
    parameter["annotation"] = python_type(row);
    parameter["doc"] = doc_line(row, value);
    out.append(parameter);
  }
  return out;
}

}  // namespace

void add_water(py::module_& module) {
  module.def("_flow_routing", &flow_routing, py::arg("heights"), py::arg("world"), py::arg("progress") = py::none());
  module.def("_fill_depressions", &fill_depressions, py::arg("heights"), py::arg("world"), py::arg("epsilon"),
             py::arg("progress") = py::none());
  module.def("_drainage_area", &drainage_area, py::arg("heights"), py::arg("world"), py::arg("method"), py::arg("keys"),
             py::arg("progress") = py::none());
  module.def("_slope", &slope, py::arg("heights"), py::arg("world"), py::arg("progress") = py::none());
  module.def("_surface_water", &surface_water, py::arg("heights"), py::arg("world"), py::arg("keys"), py::arg("progress") = py::none());
  module.def("_flow_parameters", &flow_parameters);
}

}  // namespace sansui::python

#include "nodes.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "calls.hpp"
#include "signatures.hpp"
#include "values.hpp"

namespace sansui::python {

namespace {

/// Sets one key of a [world] from Python, with its table's check.
void set_world_key(scene::WorldParams& world, const std::string& key, py::handle value) {
  const auto& table = params::table_of<scene::WorldParams>();
  const auto* row = table.find(key);
  if (row == nullptr || !row->exposed) {
    std::vector<std::string> keys;
    for (const auto& r : table.rows)
      if (r.exposed && r.superseded_in == 0) keys.push_back(r.key);
    unknown_keyword("World", key, keys);
  }
  row->set(world, to_value(*row, value, key));
}

std::string value_type_text(scene::ValueType type) {
  return std::string(scene::value_type_name(type));
}

const scene::NodeKind& kind_named(const std::string& name) {
  const scene::NodeKind* kind = scene::find_node_kind(name);
  if (kind == nullptr) throw py::value_error(fmt::format("there is no node kind '{}'", name));
  return *kind;
}

/// _run_node(kind, inputs, keys, size, cell, sea_level, progress) -> (array, notes): one node
/// computed on the given world. `inputs` holds one array or None per input slot; `keys` only
/// the kind's own keys (the Python layer, sansui/_nodes.py, took the world's and settled the
/// world: size for sources, cell and sea level for all). Input arrays may be rectangles (any
/// rows x cols, all the same); sources make size x size.
py::tuple run_node(const std::string& kind_name, const py::list& inputs, const py::dict& keys, int size, double cell_m, double sea_level_m,
                   const py::object& progress) {
  const scene::NodeKind& kind = kind_named(kind_name);
  if (!progress.is_none() && PyCallable_Check(progress.ptr()) == 0)
    throw py::type_error("progress must be a callable (stage, fraction) or None");
  std::any params = kind.make();
  for (const auto& [key, value] : keys) set_node_params(kind, params, key.cast<std::string>(), value);
  kind.validate(params);
  if (inputs.size() != kind.inputs.size())
    throw py::type_error(fmt::format("{}() takes {} input array{}, {} given", kind.name, kind.inputs.size(),
                                     kind.inputs.size() == 1 ? "" : "s", inputs.size()));
  std::vector<InputGrid> grids(kind.inputs.size());
  std::vector<const Grid<float>*> pointers(kind.inputs.size(), nullptr);
  int width = 0, height = 0;
  std::size_t first = 0;
  for (std::size_t i = 0; i < kind.inputs.size(); ++i) {
    const scene::InputSlot& slot = kind.inputs[i];
    if (inputs[i].is_none()) {
      if (!slot.optional)
        throw py::type_error(fmt::format("{}() needs its input array '{}' ({})", kind.name, slot.name, value_type_text(slot.type)));
      continue;
    }
    grids[i] = from_array(inputs[i], slot.name);
    if (grids[i].facts && grids[i].facts->type != slot.type)
      throw py::type_error(fmt::format("{}() takes {} as '{}'; the array given is {} (Sansui made it so)", kind.name,
                                       value_type_text(slot.type), slot.name, value_type_text(grids[i].facts->type)));
    const int w = grids[i].grid.width(), h = grids[i].grid.height();
    if (width != 0 && (w != width || h != height))
      throw py::value_error(fmt::format("{}(): the input arrays differ in size: '{}' is {}x{}, '{}' is {}x{} (columns x rows)", kind.name,
                                        kind.inputs[first].name, width, height, slot.name, w, h));
    if (width == 0) width = w, height = h, first = i;
    grids[i].grid.cell_size_m = cell_m;
    pointers[i] = &grids[i].grid;
  }
  scene::GraphWorld world = graph_world_of(scene::WorldParams{});
  // With input arrays, the world is theirs: their rows and columns.
  world.width = width != 0 ? width : size;
  world.height = width != 0 ? height : size;
  world.cell_m = cell_m;
  world.sea_level_m = sea_level_m;
  std::vector<std::string> notes;
  Grid<float> result = run_released(
      progress, [&](const Context& context) { return kind.run(params, pointers, world, context).grid; }, &notes);
  return py::make_tuple(to_array(std::move(result), GridFacts{world, kind.output, {0.0, 0.0}, {}}), notes);
}

/// A value as Python's, for signatures: None, bool, int, float, str or a list of floats.
py::dict parameter(const std::string& name, const char* role, py::object default_value, const std::string& annotation,
                   const std::string& doc) {
  py::dict out;
  out["name"] = name;
  out["role"] = role;
  out["default"] = std::move(default_value);
  out["annotation"] = annotation;
  out["doc"] = doc;
  return out;
}

/// The parameters of a node function, in order, for its inspect.Signature: its input arrays
/// ("input": positional or by name), contour's points or file's path ("points": the same), the kind's keys ("key"),
/// the world's keys ("world": size, cell, sea_level, crs, origin), then world and progress.
py::list node_parameters(const scene::NodeKind& kind) {
  py::list out;
  for (const auto& slot : kind.inputs)
    out.append(parameter(slot.name, "input", slot.optional ? py::object(py::none()) : py::object(py::ellipsis()),
                         slot.optional ? "Optional[ArrayLike]" : "ArrayLike", value_type_text(slot.type)));
  const std::string first = positional_key(kind);
  const std::any defaults = kind.make();
  if (!first.empty()) out.append(parameter(first, "points", py::none(), positional_type(kind), doc_line(*kind.row(first), {})));
  for (const auto& row : kind.rows) {
    if (row.key == first) continue;
    const params::Value value = kind.get(defaults, row.key);
    out.append(parameter(row.key, "key", to_python(value), python_type(row), doc_line(row, value)));
  }
  const auto& world_table = params::table_of<scene::WorldParams>();
  const scene::WorldParams world_defaults;
  for (const auto& key : world_keys_of(kind)) {
    const auto* row = world_table.find(key);
    const std::string type = python_type(*row);
    out.append(parameter(key, "world", py::none(), type.starts_with("Optional[") ? type : "Optional[" + type + "]",
                         doc_line(*row, row->get(world_defaults))));
  }
  out.append(parameter("world", "world", py::none(), "Optional[World]", "the world to work on"));
  out.append(parameter("progress", "progress", py::none(), "Progress", "a callable (stage, fraction)"));
  return out;
}

}  // namespace

scene::GraphWorld graph_world_of(const scene::WorldParams& world) {
  scene::GraphWorld graph;
  graph.width = graph.height = static_cast<int>(world.size);
  graph.cell_m = world.cell_m, graph.sea_level_m = world.sea_level_m;
  graph.base_dir = std::filesystem::current_path().string();
  return graph;
}

void set_node_params(const scene::NodeKind& kind, std::any& params, const std::string& key, py::handle value) {
  const params::ParamInfo* row = kind.row(key);
  if (row == nullptr) unknown_keyword(kind.name, key, call_keywords(kind));
  kind.set(params, key, to_value(*row, value, key));
}

void add_node_functions(py::module_& module) {
  module.def(
      "node_kinds",
      [] {
        py::list kinds;
        for (const scene::NodeKind& kind : scene::all_node_kinds()) {
          if (!has_function(kind)) continue;
          py::list inputs;
          for (const auto& slot : kind.inputs) inputs.append(py::make_tuple(slot.name, value_type_text(slot.type), slot.optional));
          kinds.append(py::dict(py::arg("name") = kind.name, py::arg("group") = kind.group, py::arg("help") = kind.help,
                                py::arg("inputs") = inputs, py::arg("output") = value_type_text(kind.output)));
        }
        return kinds;
      },
      "node_kinds() -> list[dict]: every node kind that is a function: name, group, help, inputs [(name, type, optional)], output type");
  // For tests of zero copy: where the samples of an array Sansui made live, and whether an array
  // handed in would be read in place.
  module.def("_grid_address", [](py::handle array) { return held_grid_address(array); });
  module.def("_reads_in_place", [](py::handle array) { return !from_array(array, "array").copied; });
  // What the Python layer (sansui/_nodes.py) builds the node functions from.
  module.def("_grid_facts", &grid_facts, "The world of an array Sansui made (dict), or None");
  module.def("_run_node", &run_node, py::arg("kind"), py::arg("inputs"), py::arg("keys"), py::arg("size"), py::arg("cell"),
             py::arg("sea_level"), py::arg("progress") = py::none());
  module.def("_node_parameters", [](const std::string& kind) { return node_parameters(kind_named(kind)); });
  module.def("_unknown_keyword", [](const std::string& function, const std::string& key, const std::vector<std::string>& known) {
    unknown_keyword(function, key, known);
  });
  module.def("_node_docstring", [](const std::string& kind) { return node_docstring(kind_named(kind)); });
}

void add_world(py::module_& module) {
  py::class_<scene::WorldParams>(module, "World", world_docstring().c_str())
      .def(py::init([](const py::kwargs& kwargs) {
        scene::WorldParams world;
        for (const auto& [key, value] : kwargs) set_world_key(world, key.cast<std::string>(), value);
        params::validate(world);
        return world;
      }))
      .def("__getattr__",
           [](const scene::WorldParams& world, const std::string& key) {
             const auto* row = params::table_of<scene::WorldParams>().find(key);
             if (row == nullptr || !row->exposed) throw py::attribute_error(fmt::format("World has no key '{}'", key));
             return to_python(row->get(world));
           })
      .def(
          "to_dict",
          [](const scene::WorldParams& world) {
            py::dict dict;
            for (const auto& row : params::table_of<scene::WorldParams>().rows) {
              if (!row.exposed || row.superseded_in != 0) continue;
              const params::Value value = row.get(world);
              if (!std::holds_alternative<std::monostate>(value)) dict[row.key.c_str()] = to_python(value);
            }
            return dict;
          },
          "The world as the [world] table of a recipe (unset keys left out)")
      .def("__repr__", [](const scene::WorldParams& world) {
        return fmt::format("sansui.World(size={}, cell={}, sea_level={})", world.size, params::format_number(world.cell_m),
                           params::format_number(world.sea_level_m));
      });
}

}  // namespace sansui::python

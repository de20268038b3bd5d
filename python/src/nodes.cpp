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

const std::vector<std::string> world_keys = {"size", "cell", "sea_level"};

bool is_world_key(std::string_view key) {
  return std::find(world_keys.begin(), world_keys.end(), key) != world_keys.end();
}

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

/// The arrays and keyword arguments of one node call, sorted out.
struct NodeCall {
  std::any params;
  std::vector<py::object> inputs;  // one per slot, None where not given
  py::object progress = py::none();
  std::optional<scene::WorldParams> world;
  scene::WorldParams overrides;
  std::vector<std::string> overridden;
};

NodeCall read_call(const scene::NodeKind& kind, const py::args& args, const py::kwargs& kwargs) {
  NodeCall call;
  call.params = kind.make();
  call.inputs.assign(kind.inputs.size(), py::none());
  std::size_t positional = args.size();
  // A kind that takes no arrays but points (contour): its one positional argument is them.
  if (kind.inputs.empty() && args.size() == 1 && kind.row("points") != nullptr) {
    set_node_params(kind, call.params, "points", args[0]);
    positional = 0;
  } else if (args.size() > kind.inputs.size()) {
    throw py::type_error(fmt::format("{}() takes {} input array{}, {} given", kind.name, kind.inputs.size(),
                                     kind.inputs.size() == 1 ? "" : "s", args.size()));
  }
  for (std::size_t i = 0; i < positional; ++i) call.inputs[i] = args[i];
  for (const auto& [key_object, value] : kwargs) {
    const auto key = key_object.cast<std::string>();
    if (key == "progress") {
      if (!value.is_none() && PyCallable_Check(value.ptr()) == 0)
        throw py::type_error("progress must be a callable (stage, fraction) or None");
      call.progress = py::reinterpret_borrow<py::object>(value);
    } else if (key == "world") {
      if (!value.is_none()) call.world = value.cast<scene::WorldParams>();
    } else if (kind.row(key) != nullptr) {
      set_node_params(kind, call.params, key, value);
    } else if (is_world_key(key)) {
      set_world_key(call.overrides, key, value);
      call.overridden.push_back(key);
    } else {
      const auto slot = std::find_if(kind.inputs.begin(), kind.inputs.end(), [&](const auto& s) { return s.name == key; });
      if (slot == kind.inputs.end()) unknown_keyword(kind.name, key, call_keywords(kind));
      auto& input = call.inputs[static_cast<std::size_t>(slot - kind.inputs.begin())];
      if (!input.is_none()) throw py::type_error(fmt::format("{}() got multiple values for input '{}'", kind.name, key));
      input = py::reinterpret_borrow<py::object>(value);
    }
  }
  kind.validate(call.params);
  return call;
}

py::object call_node(const scene::NodeKind& kind, const py::args& args, const py::kwargs& kwargs) {
  NodeCall call = read_call(kind, args, kwargs);
  std::vector<InputGrid> grids(kind.inputs.size());
  std::optional<GridFacts> facts;
  for (std::size_t i = 0; i < kind.inputs.size(); ++i) {
    const scene::InputSlot& slot = kind.inputs[i];
    if (call.inputs[i].is_none()) {
      if (!slot.optional)
        throw py::type_error(fmt::format("{}() needs its input array '{}' ({})", kind.name, slot.name, value_type_text(slot.type)));
      continue;
    }
    grids[i] = from_array(call.inputs[i], slot.name);
    if (grids[i].facts && grids[i].facts->type != slot.type)
      throw py::type_error(fmt::format("{}() takes {} as '{}'; the array given is {} (Sansui made it so)", kind.name,
                                       value_type_text(slot.type), slot.name, value_type_text(grids[i].facts->type)));
    if (!facts && grids[i].facts) facts = grids[i].facts;
  }
  // The world: given, else the one the input arrays were made on, else the default; its size is
  // the arrays' side, and size=, cell=, sea_level= change what they name.
  scene::GraphWorld world = call.world ? graph_world_of(*call.world) : facts ? facts->world : graph_world_of(scene::WorldParams{});
  int side = 0;
  for (std::size_t i = 0; i < grids.size(); ++i) {
    if (call.inputs[i].is_none()) continue;
    const int width = grids[i].grid.width();
    if (side != 0 && width != side)
      throw py::value_error(fmt::format("{}(): the input arrays differ in size: '{}' is {}x{}, '{}' is {}x{}", kind.name,
                                        kind.inputs[0].name, side, side, kind.inputs[i].name, width, width));
    side = width;
  }
  if (side != 0) {
    if (call.world && call.world->size != side)
      throw py::value_error(fmt::format("{}(): the input arrays are {}x{} samples; the world given is {}x{}", kind.name, side, side,
                                        call.world->size, call.world->size));
    world.size = side;
  }
  for (const std::string& key : call.overridden) {
    if (key == "size") {
      if (side != 0 && call.overrides.size != side)
        throw py::value_error(
            fmt::format("{}(): size={} but the input arrays are {}x{} samples", kind.name, call.overrides.size, side, side));
      world.size = static_cast<int>(call.overrides.size);
    }
    if (key == "cell") world.cell_m = call.overrides.cell_m;
    if (key == "sea_level") world.sea_level_m = call.overrides.sea_level_m;
  }
  std::vector<const Grid<float>*> pointers(grids.size(), nullptr);
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (!call.inputs[i].is_none()) {
      grids[i].grid.cell_size_m = world.cell_m;
      pointers[i] = &grids[i].grid;
    }
  Grid<float> result = run_released(call.progress, [&](const Context& context) { return kind.run(call.params, pointers, world, context); });
  return to_array(std::move(result), GridFacts{world, kind.output});
}

}  // namespace

scene::GraphWorld graph_world_of(const scene::WorldParams& world) {
  return {static_cast<int>(world.size), world.cell_m, world.sea_level_m, std::filesystem::current_path().string()};
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
          py::list inputs;
          for (const auto& slot : kind.inputs) inputs.append(py::make_tuple(slot.name, value_type_text(slot.type), slot.optional));
          kinds.append(py::dict(py::arg("name") = kind.name, py::arg("group") = kind.group, py::arg("help") = kind.help,
                                py::arg("inputs") = inputs, py::arg("output") = value_type_text(kind.output)));
        }
        return kinds;
      },
      "node_kinds() -> list[dict]: every node kind: name, group, help, inputs [(name, type, optional)], output type");
  // For tests of zero copy: where the samples of an array Sansui made live, and whether an array
  // handed in would be read in place.
  module.def("_grid_address", [](py::handle array) { return held_grid_address(array); });
  module.def("_reads_in_place", [](py::handle array) { return !from_array(array, "array").copied; });
  for (const scene::NodeKind& kind : scene::all_node_kinds()) {
    const scene::NodeKind* k = &kind;
    module.def(
        kind.name.c_str(), [k](const py::args& args, const py::kwargs& kwargs) { return call_node(*k, args, kwargs); },
        node_docstring(kind).c_str());
  }
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

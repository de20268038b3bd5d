#include "recipes.hpp"

#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/stl.h>
#include <toml++/toml.h>

#include "arrays.hpp"
#include "calls.hpp"
#include "nodes.hpp"
#include "scene/evaluator.hpp"
#include "scene/graph.hpp"
#include "scene/pipeline.hpp"
#include "scene/recipe_file.hpp"
#include "values.hpp"

namespace sansui::python {

namespace {

/// A recipe and the warnings its reading gave.
struct PyRecipe {
  scene::Recipe recipe;
  std::vector<std::string> warnings;
};

/// A Python value as TOML, for recipes given as dicts. Throws TypeError for what TOML cannot hold.
toml::table to_toml_table(py::handle dict, const std::string& where);

void append_toml(toml::array& array, py::handle value, const std::string& where);

template <class Insert>
void insert_toml(py::handle value, const std::string& where, Insert&& insert) {
  if (py::isinstance<py::bool_>(value))
    insert(value.cast<bool>());
  else if (PyLong_Check(value.ptr()) != 0)
    insert(value.cast<std::int64_t>());
  else if (PyFloat_Check(value.ptr()) != 0)
    insert(value.cast<double>());
  else if (py::isinstance<py::str>(value))
    insert(value.cast<std::string>());
  else if (PyObject_HasAttrString(value.ptr(), "__fspath__") != 0)
    insert(py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>());
  else if (py::isinstance<py::dict>(value))
    insert(to_toml_table(value, where));
  else if (py::isinstance<scene::WorldParams>(value))
    insert(to_toml_table(value.attr("to_dict")(), where));
  else if (PyObject_HasAttrString(value.ptr(), "tolist") != 0)
    insert_toml(value.attr("tolist")(), where, insert);
  else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    toml::array array;
    for (py::handle item : value) append_toml(array, item, where);
    insert(std::move(array));
  } else {
    throw py::type_error(fmt::format("recipe: {} is a {}; a recipe holds numbers, text, lists and dicts", where,
                                     py::str(py::type::of(value).attr("__name__")).cast<std::string>()));
  }
}

void append_toml(toml::array& array, py::handle value, const std::string& where) {
  insert_toml(value, where, [&](auto&& v) { array.push_back(std::forward<decltype(v)>(v)); });
}

toml::table to_toml_table(py::handle dict, const std::string& where) {
  if (!py::isinstance<py::dict>(dict)) throw py::type_error(fmt::format("recipe: {} must be a dict", where.empty() ? "the recipe" : where));
  toml::table table;
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(dict)) {
    if (!py::isinstance<py::str>(key))
      throw py::type_error(fmt::format("recipe: the keys of {} must be str", where.empty() ? "the recipe" : where));
    const auto name = key.cast<std::string>();
    if (value.is_none()) continue;  // None: unset, as a key left out
    // An empty list: none, as a key left out ([[output]] tables that are not there).
    if ((py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) && py::len(value) == 0) continue;
    const std::string inner = where.empty() ? name : fmt::format("{}.{}", where, name);
    insert_toml(value, inner, [&](auto&& v) { table.insert_or_assign(name, std::forward<decltype(v)>(v)); });
  }
  return table;
}

/// Messages about a recipe made from a dict name no line of the TOML text it went through.
[[noreturn]] void rethrow_without_line(const InputError& error, const std::string& source) {
  static const std::regex line(R"(^recipe:\d+(:\d+)?: )");
  throw py::value_error(std::regex_replace(std::string(error.what()), line, source + ": "));
}

PyRecipe recipe_from_dict(py::handle dict, const std::filesystem::path& base_dir) {
  std::ostringstream text;
  text << to_toml_table(dict, "");
  try {
    scene::LoadedRecipe loaded = scene::parse_recipe_toml(text.str(), "recipe", base_dir);
    return {std::move(loaded.recipe), std::move(loaded.warnings)};
  } catch (const InputError& error) {
    rethrow_without_line(error, "recipe");
  }
}

py::object json_to_python(const nlohmann::json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

PyRecipe recipe_from(py::handle source) {
  if (source.is_none()) return recipe_from_dict(py::dict(), std::filesystem::current_path());
  if (py::isinstance<py::dict>(source)) return recipe_from_dict(source, std::filesystem::current_path());
  if (py::isinstance<PyRecipe>(source)) return source.cast<PyRecipe>();
  if (py::isinstance<py::str>(source) || PyObject_HasAttrString(source.ptr(), "__fspath__") != 0) {
    const auto path = py::str(py::module_::import("os").attr("fspath")(source)).cast<std::string>();
    scene::LoadedRecipe loaded = scene::load_recipe(path);
    return {std::move(loaded.recipe), std::move(loaded.warnings)};
  }
  throw py::type_error(fmt::format("a recipe is a scene file's path, a dict or a sansui.Recipe; got {}",
                                   py::str(py::type::of(source).attr("__name__")).cast<std::string>()));
}

/// The recipe as a dict with one more entry in its list `section` ("node", "output").
PyRecipe with_entry(const PyRecipe& self, const char* section, py::dict entry) {
  auto dict = json_to_python(scene::recipe_to_json(self.recipe)).cast<py::dict>();
  py::list list = dict.contains(section) ? py::list(dict[section]) : py::list();
  list.append(std::move(entry));
  dict[section] = list;
  // The first node makes the recipe a graph, whose nodes are its source of heights.
  if (std::string_view(section) == "node" && self.recipe.nodes.empty()) dict["source"] = "none";
  return recipe_from_dict(dict, self.recipe.base_dir.empty() ? std::filesystem::current_path() : self.recipe.base_dir);
}

py::list run(const PyRecipe& self, const py::object& out_dir, const py::object& progress, const py::object& cache) {
  scene::Recipe recipe = self.recipe;
  if (!out_dir.is_none())
    recipe = scene::with_outputs_in(std::move(recipe), py::str(py::module_::import("os").attr("fspath")(out_dir)).cast<std::string>());
  scene::RunOptions options;
  options.provenance = {{"program", "sansui"}, {"version", SANSUI_VERSION}, {"command", "python"}};
  if (!cache.is_none()) options.cache_dir = py::str(py::module_::import("os").attr("fspath")(cache)).cast<std::string>();
  const scene::RunReport report =
      run_released(progress, [&](const Context& context) { return scene::run_recipe(recipe, options, context); });
  py::list written;
  for (const auto& path : report.written) written.append(std::filesystem::absolute(path).lexically_normal().string());
  return written;
}

}  // namespace

void add_recipes(py::module_& module) {
  py::class_<PyRecipe>(module, "Recipe",
                       "Recipe(source=None): a whole recipe, as `sansui run` reads one. `source` is a scene file (.toml) or an "
                       "output's sidecar (.json), a dict shaped like a scene file ({'world': {...}, 'node': [{...}], 'output': "
                       "[{...}]}), another Recipe, or None for an empty one to build with node() and output().")
      .def(py::init([](const py::object& source) { return recipe_from(source); }), py::arg("source") = py::none())
      .def_static(
          "from_toml",
          [](const std::string& text, const py::object& base_dir) {
            const std::filesystem::path base =
                base_dir.is_none() ? std::filesystem::current_path()
                                   : std::filesystem::path(py::str(py::module_::import("os").attr("fspath")(base_dir)).cast<std::string>());
            scene::LoadedRecipe loaded = scene::parse_recipe_toml(text, "recipe", base);
            return PyRecipe{std::move(loaded.recipe), std::move(loaded.warnings)};
          },
          py::arg("text"), py::arg("base_dir") = py::none(),
          "A recipe from TOML text; relative file names start at base_dir (default: here)")
      .def(
          "node",
          [](const PyRecipe& self, const std::string& id, const std::string& kind, const py::args& inputs, const py::kwargs& keys) {
            const scene::NodeKind* node_kind = scene::find_node_kind(kind);
            if (node_kind == nullptr) {
              std::vector<std::string> names;
              for (const auto& k : scene::all_node_kinds()) names.push_back(k.name);
              throw py::value_error(
                  fmt::format("node {}: kind '{}' is not allowed: it must be one of {}", id, kind, fmt::join(names, ", ")));
            }
            // The keys are checked here, with their Python names, before the recipe reads them.
            std::any params = node_kind->make();
            py::dict entry;
            entry["id"] = id;
            entry["kind"] = kind;
            py::list ids;
            for (py::handle input : inputs) ids.append(input);
            if (!inputs.empty()) entry["inputs"] = ids;
            for (const auto& [key, value] : keys) {
              set_node_params(*node_kind, params, key.cast<std::string>(), value);
              entry[key] = value;
            }
            return with_entry(self, "node", entry);
          },
          py::arg("id"), py::arg("kind"),
          "A copy with one more node: node(id, kind, *input_ids, **keys), e.g. node('eroded', 'erode', 'hills', stage='mature'). "
          "The first node makes the recipe a graph: its nodes replace any source")
      .def(
          "output",
          [](const PyRecipe& self, const std::string& file, const py::kwargs& keys) {
            py::dict entry;
            entry["file"] = file;
            for (const auto& [key, value] : keys) entry[key] = value;
            return with_entry(self, "output", entry);
          },
          py::arg("file"), "A copy with one more output: output(file, **keys), e.g. output('t.tif', node='eroded')")
      .def_property_readonly(
          "world", [](const PyRecipe& self) { return self.recipe.world; }, "The recipe's [world]")
      .def_property_readonly(
          "warnings", [](const PyRecipe& self) { return self.warnings; }, "What reading it warned of")
      .def_property_readonly(
          "node_ids",
          [](const PyRecipe& self) {
            std::vector<std::string> ids;
            for (const auto& n : self.recipe.nodes) ids.push_back(n.id);
            return ids;
          },
          "The ids of its nodes, in file order")
      .def(
          "to_dict", [](const PyRecipe& self) { return json_to_python(scene::recipe_to_json(self.recipe)); },
          "The recipe as a dict, shaped like the scene file")
      .def(
          "to_toml", [](const PyRecipe& self) { return scene::recipe_to_toml(self.recipe); },
          "The recipe as a complete, commented scene file")
      .def(
          "save",
          [](const PyRecipe& self, const py::object& path) {
            scene::save_recipe(py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>(), self.recipe);
          },
          py::arg("path"), "Writes the recipe as a scene file (atomically), file names relative to its directory")
      .def(
          "heights",
          [](const PyRecipe& self, const py::object& node, const py::object& progress) -> py::array {
            if (node.is_none()) {
              Heightfield heights =
                  run_released(progress, [&](const Context& context) { return scene::recipe_heights(self.recipe, context); });
              GridFacts facts{graph_world_of(self.recipe.world), scene::ValueType::heights};
              facts.world.base_dir = self.recipe.base_dir.string();
              return to_array(std::move(heights), facts);
            }
            const auto id = node.cast<std::string>();
            const auto found = std::find_if(self.recipe.nodes.begin(), self.recipe.nodes.end(), [&](const auto& n) { return n.id == id; });
            if (found == self.recipe.nodes.end()) throw py::value_error(fmt::format("the recipe has no node '{}'", id));
            scene::check_graph(self.recipe);
            scene::GraphWorld world = graph_world_of(self.recipe.world);
            world.base_dir = self.recipe.base_dir.string();
            Grid<float> grid = run_released(progress, [&](const Context& context) {
              scene::Evaluator evaluator;
              auto results = evaluator.evaluate(self.recipe.nodes, world, {id}, context);
              return Grid<float>(*results.at(id));  // the evaluator's is shared: one copy
            });
            return to_array(std::move(grid), GridFacts{world, found->node_kind().output});
          },
          py::arg("node") = py::none(), py::arg("progress") = py::none(),
          "The terrain its outputs are made from (float32, rows x cols, metres), or the result of node `node` (one copy)")
      .def("run", &run, py::arg("out_dir") = py::none(), py::arg("progress") = py::none(), py::arg("cache") = py::none(),
           "Runs the recipe as `sansui run` does and returns the files written. out_dir: every output moves there")
      .def("__repr__", [](const PyRecipe& self) {
        return fmt::format("sansui.Recipe(<{} nodes, {} outputs, world {}x{}>)", self.recipe.nodes.size(), self.recipe.outputs.size(),
                           self.recipe.world.size, self.recipe.world.size);
      });

  module.def(
      "run",
      [](const py::object& recipe, const py::object& out_dir, const py::object& progress, const py::object& cache) {
        return run(recipe_from(recipe), out_dir, progress, cache);
      },
      py::arg("recipe"), py::arg("out_dir") = py::none(), py::arg("progress") = py::none(), py::arg("cache") = py::none(),
      "run(recipe, out_dir=None, progress=None, cache=None) -> list[str]: runs a recipe (a scene file's path, a dict or a "
      "Recipe) as `sansui run` does, and returns the files written");
}

}  // namespace sansui::python

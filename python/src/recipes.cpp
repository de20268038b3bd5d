#include "recipes.hpp"

#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "calls.hpp"
#include "nodes.hpp"
#include "recipe_source.hpp"
#include "scene/evaluator.hpp"
#include "scene/graph.hpp"
#include "scene/pipeline.hpp"
#include "scene/recipe_file.hpp"
#include "values.hpp"

namespace sansui::python {

namespace {

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

/// The facts of an array made from `recipe`: its world's cell, sea level, origin and CRS.
GridFacts recipe_facts(const scene::Recipe& recipe, scene::ValueType type) {
  GridFacts facts{graph_world_of(recipe.world), type, {0.0, 0.0}, {}};
  facts.world.base_dir = recipe.base_dir.string();
  const auto [east, south] = scene::world_sample_origin(recipe.world);
  facts.sample_origin = {east, south == 0.0 ? 0.0 : -south};
  facts.crs = recipe.world.crs.empty() ? recipe.georeference.crs : recipe.world.crs;
  return facts;
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
          "_heights",
          [](const PyRecipe& self, const py::object& node, const py::object& progress) -> py::array {
            if (node.is_none()) {
              Heightfield heights =
                  run_released(progress, [&](const Context& context) { return scene::recipe_heights(self.recipe, context); });
              GridFacts facts = recipe_facts(self.recipe, scene::ValueType::heights);
              facts.world.cell_m = heights.cell_size_m;
              facts.sample_origin = {heights.origin_x_m, heights.origin_y_m == 0.0 ? 0.0 : -heights.origin_y_m};
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
              return Grid<float>(*results.at(id).grid);  // the evaluator's is shared: one copy
            });
            return to_array(std::move(grid), recipe_facts(self.recipe, found->node_kind().output));
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

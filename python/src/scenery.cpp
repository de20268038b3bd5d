#include "scenery.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "calls.hpp"
#include "mesh/axes.hpp"
#include "mesh/heightfield_mesh.hpp"
#include "nodes.hpp"
#include "recipe_source.hpp"
#include "scene/climate.hpp"
#include "scene/node_kinds.hpp"
#include "scene/plants.hpp"
#include "scene/scenery.hpp"
#include "signatures.hpp"
#include "values.hpp"

namespace sansui::python {

namespace {

// ---- parameter_tables() ----------------------------------------------------------------------

py::object optional_number(const std::optional<double>& value) {
  return value ? py::object(py::float_(*value)) : py::object(py::none());
}

/// One row as a dict; `key` is the row's key within its table (without the section's prefix).
py::dict row_dict(const params::ParamInfo& row, const std::string& key, const params::Value& default_value) {
  py::dict out;
  out["key"] = key;
  out["kind"] = params::kind_name(row.kind);
  out["unit"] = row.unit;
  out["help"] = row.help;
  out["group"] = row.group;
  out["optional"] = row.optional;
  out["default"] = to_python(default_value);
  out["default_text"] = params::default_text(row, default_value);
  out["allowed"] = params::allowed_text(row);
  out["min"] = optional_number(row.limits.min);
  out["max"] = optional_number(row.limits.max);
  out["min_exclusive"] = row.limits.min_exclusive;
  out["max_exclusive"] = row.limits.max_exclusive;
  out["choices"] = row.limits.choices;
  out["count"] = row.kind == params::Kind::reals ? py::cast(std::vector<std::size_t>{row.limits.min_count, row.limits.max_count})
                                                 : py::object(py::none());
  return out;
}

bool shown(const params::ParamInfo& row) {
  return row.exposed && row.superseded_in == 0;
}

/// The rows of one section of the recipe table, keys without the section's prefix.
py::dict section_table(const scene::Section& section) {
  static const scene::Recipe defaults;
  const std::string prefix = section.name + ".";
  py::list rows;
  for (const auto& row : scene::recipe_table().rows)
    if (shown(row) && scene::section_of(row.key) == section.name)
      rows.append(row_dict(row, row.key.substr(prefix.size()), row.get(defaults)));
  py::dict table;
  table["title"] = section.title;
  table["rows"] = rows;
  return table;
}

py::dict node_table(const scene::NodeKind& kind) {
  const std::any defaults = kind.make();
  py::list rows;
  for (const auto& row : kind.rows)
    if (shown(row)) rows.append(row_dict(row, row.key, kind.get(defaults, row.key)));
  py::dict table;
  table["title"] = kind.help;
  table["rows"] = rows;
  return table;
}

py::dict parameter_tables() {
  py::dict tables;
  for (const scene::Section& section : scene::recipe_sections())
    if (section.name == "world") tables["world"] = section_table(section);
  for (const scene::NodeKind& kind : scene::all_node_kinds()) tables[("node." + kind.name).c_str()] = node_table(kind);
  for (const scene::Section* section : scene::scenery_sections()) tables[section->name.c_str()] = section_table(*section);
  return tables;
}

// ---- scenery() -------------------------------------------------------------------------------

void check_progress(const py::object& progress) {
  if (!progress.is_none() && PyCallable_Check(progress.ptr()) == 0)
    throw py::type_error("progress must be a callable (stage, fraction) or None");
}

/// The dtype of scene::SceneryPlant: its fields at their offsets.
py::dtype plant_dtype() {
  using P = scene::SceneryPlant;
  py::dict fields;
  fields["names"] = std::vector<std::string>{"x", "y", "z", "species", "variant", "scale", "rotation", "layer"};
  fields["formats"] = std::vector<std::string>{"<f4", "<f4", "<f4", "<u2", "<u2", "<f4", "<f4", "u1"};
  fields["offsets"] = std::vector<std::size_t>{offsetof(P, x_m),     offsetof(P, y_m),   offsetof(P, z_m),          offsetof(P, species),
                                               offsetof(P, variant), offsetof(P, scale), offsetof(P, rotation_rad), offsetof(P, layer)};
  fields["itemsize"] = sizeof(P);
  return py::dtype::from_args(fields);
}

/// An RGBA image as a (rows, cols, channels) uint8 array over its pixels: all four channels, or
/// the first three (a view that steps over alpha).
py::array image_array(const Image& image, int channels, const py::capsule& base) {
  const auto rows = static_cast<py::ssize_t>(image.height()), cols = static_cast<py::ssize_t>(image.width());
  const auto pixel = static_cast<py::ssize_t>(sizeof(Rgba8));
  return py::array(py::dtype::of<std::uint8_t>(), {rows, cols, static_cast<py::ssize_t>(channels)}, {cols * pixel, pixel, py::ssize_t{1}},
                   reinterpret_cast<const std::uint8_t*>(image.data()), base);
}

py::dict scenery(const py::object& source, const py::object& progress) {
  check_progress(progress);
  const PyRecipe recipe = recipe_from(source);
  auto parts = std::make_shared<scene::Scenery>(
      run_released(progress, [&](const Context& context) { return scene::make_scenery(recipe.recipe, context); }));
  const py::capsule base = keep_alive(parts);
  py::dict out;
  out["cell"] = parts->heights.cell_size_m;
  out["sea_level"] = parts->sea_level_m;
  out["sea"] = parts->sea;
  out["origin"] = py::make_tuple(parts->origin[0], parts->origin[1]);
  GridFacts facts{graph_world_of(recipe.recipe.world), scene::ValueType::heights, {0.0, 0.0}, {}};
  facts.world.base_dir = recipe.recipe.base_dir.string();
  facts.world.cell_m = parts->heights.cell_size_m;
  facts.sample_origin = {parts->origin[0], parts->origin[1]};
  facts.crs = recipe.recipe.world.crs.empty() ? recipe.recipe.georeference.crs : recipe.recipe.world.crs;
  out["heights"] = to_array(std::move(parts->heights), facts);
  out["colour"] = image_array(parts->colour, 3, base);
  out["splat"] = image_array(parts->splat, 4, base);
  const auto rows = static_cast<py::ssize_t>(parts->water_m.height()), cols = static_cast<py::ssize_t>(parts->water_m.width());
  out["water"] = array_over(parts->water_m.data(), {rows, cols}, base);
  out["plants"] = py::array(plant_dtype(), {static_cast<py::ssize_t>(parts->plants.size())},
                            {static_cast<py::ssize_t>(sizeof(scene::SceneryPlant))}, parts->plants.data(), base);
  out["species"] = parts->species;
  out["season"] = std::string(scene::name_of(parts->season));
  out["plant_snow"] = parts->plant_snow;
  return out;
}

// ---- tree() and terrain_mesh() ----------------------------------------------------------------

/// Sets the recipe key `key` ("tree.species") from a Python value, named `name` in messages.
void set_recipe_key(scene::Recipe& recipe, const std::string& key, py::handle value, std::string_view name) {
  const auto* row = scene::recipe_table().find(key);
  row->set(recipe, to_value(*row, value, name));
}

/// A mesh's vertices (k, 3), faces (m, 3) and, where it has them, per-vertex normals and colours,
/// over the mesh's own buffers.
py::dict mesh_arrays(std::shared_ptr<TriangleMesh> mesh) {
  const py::capsule base = keep_alive(mesh);
  const auto vertices = static_cast<py::ssize_t>(mesh->positions.size());
  py::dict out;
  out["vertices"] = array_over(reinterpret_cast<const float*>(mesh->positions.data()), {vertices, 3}, base);
  out["faces"] = array_over(mesh->indices.data(), {static_cast<py::ssize_t>(mesh->triangle_count()), 3}, base);
  if (!mesh->normals.empty()) out["normals"] = array_over(reinterpret_cast<const float*>(mesh->normals.data()), {vertices, 3}, base);
  if (!mesh->colors.empty()) out["colours"] = array_over(reinterpret_cast<const float*>(mesh->colors.data()), {vertices, 3}, base);
  return out;
}

/// The plants' variant, checked as a table's integer row would be: TypeError or ValueError.
std::int64_t variant_of(py::handle variant) {
  params::ParamInfo row;
  row.kind = params::Kind::integer;
  row.limits.min = 0;
  row.limits.max = vegetation::variants_per_species - 1;
  return std::get<std::int64_t>(to_value(row, variant, "variant"));
}

py::dict tree(const py::object& species, const py::object& variant, const py::object& season, const py::object& seed,
              const py::object& snow) {
  scene::Recipe recipe;
  set_recipe_key(recipe, "tree.species", species, "species");
  // `sansui tree`'s seed picks the variant (seed mod variants_per_species): a variant is the seed
  // that picks it.
  const bool variant_given = !variant.is_none();
  const std::int64_t given = variant_given ? variant_of(variant) : 0;
  if (variant_given) recipe.tree.seed = static_cast<std::uint64_t>(given);
  if (!seed.is_none()) {
    set_recipe_key(recipe, "tree.seed", seed, "seed");
    const auto chosen = static_cast<std::int64_t>(recipe.tree.seed % vegetation::variants_per_species);
    if (variant_given && given != chosen)
      throw py::value_error(fmt::format("variant {} and seed {} disagree: seed {} is variant {} (give one of them)", given,
                                        recipe.tree.seed, recipe.tree.seed, chosen));
  }
  if (!season.is_none()) set_recipe_key(recipe, "season.season", season, "season");
  if (!snow.is_none()) set_recipe_key(recipe, "tree.winter_snow", snow, "snow");
  auto mesh = std::make_shared<TriangleMesh>(run_released(py::none(), [&](const Context&) { return scene::tree_mesh_of(recipe); }));
  mesh::turn_to_z_up(*mesh);
  return mesh_arrays(std::move(mesh));
}

py::tuple terrain_mesh(const py::object& heights, const py::object& world, const py::object& cell, const py::object& progress) {
  check_progress(progress);
  InputGrid input = from_array(heights, "heights");
  double cell_m = input.facts ? input.facts->world.cell_m : scene::WorldParams{}.cell_m;
  if (!world.is_none()) {
    if (!py::isinstance<scene::WorldParams>(world))
      throw py::type_error(
          fmt::format("world must be a sansui.World; got {}", py::str(py::type::of(world).attr("__name__")).cast<std::string>()));
    cell_m = world.cast<scene::WorldParams>().cell_m;
  }
  if (!cell.is_none()) {
    const auto* row = params::table_of<scene::WorldParams>().find("cell");
    cell_m = std::get<double>(to_value(*row, cell, "cell"));
  }
  if (input.grid.width() < 2) throw py::value_error("heights must have at least 2x2 samples to make a mesh of");
  input.grid.cell_size_m = cell_m;
  auto mesh = std::make_shared<TriangleMesh>(run_released(progress, [&](const Context&) { return mesh::heightfield_to_mesh(input.grid); }));
  mesh::turn_to_z_up(*mesh);
  const py::dict arrays = mesh_arrays(std::move(mesh));
  return py::make_tuple(arrays["vertices"], arrays["faces"]);
}

}  // namespace

void add_scenery(py::module_& module) {
  // The docstrings carry their own signatures (scenery_stubs.cpp).
  py::options options;
  options.disable_function_signatures();
  module.def("parameter_tables", &parameter_tables, scenery_docstrings().at("parameter_tables").c_str());
  module.def("scenery", &scenery, py::arg("recipe"), py::arg("progress") = py::none(), scenery_docstrings().at("scenery").c_str());
  module.def("tree", &tree, py::arg("species"), py::arg("variant") = py::none(), py::arg("season") = py::none(),
             py::arg("seed") = py::none(), py::kw_only(), py::arg("snow") = py::none(), scenery_docstrings().at("tree").c_str());
  module.def("terrain_mesh", &terrain_mesh, py::arg("heights"), py::arg("world") = py::none(), py::kw_only(), py::arg("cell") = py::none(),
             py::arg("progress") = py::none(), scenery_docstrings().at("terrain_mesh").c_str());
}

}  // namespace sansui::python

#include "scene/plants.hpp"

#include <algorithm>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/params_text.hpp"
#include "io/text_file.hpp"
#include "look/render_params.hpp"
#include "scene/climate.hpp"
#include "scene/look.hpp"
#include "scene/painter.hpp"
#include "scene/sources.hpp"

namespace sansui::scene {
namespace {

double highest(const Heightfield& heights) {
  float high = heights.data()[0];
  for (float value : heights.values()) high = std::max(high, value);
  return high;
}

}  // namespace

vegetation::PlacementRules placement_rules(const Recipe& looked, const Heightfield& heights) {
  const look::RenderParams& r = looked.render;
  vegetation::PlacementRules rules;
  rules.sea_level_m = look::effective_sea_level(r, heights);
  // Trees stop where the renderer's rock colour starts: at the tree line in metres (lines =
  // "climate", the same on every tile) or at Table 4's fraction of the highest point ("paper").
  const look::RenderParams lines = look::with_fallbacks(r);
  const double scale_m = look::band_scale_m(lines.land, rules.sea_level_m, highest(heights));
  rules.tree_line_m = rules.sea_level_m + look::tree_line_fraction(lines.land) * scale_m;
  const double above_sea = lines.land.lines == look::LandLines::climate ? scale_m : std::max(highest(heights) - rules.sea_level_m, 1.0);
  rules.water_edge_m = looked.vegetation.water_edge * above_sea;
  rules.tree_density = looked.vegetation.density.value_or(0.0);
  rules.ground_density = looked.vegetation.ground_density.value_or(0.0);
  rules.season = season_of(looked);
  rules.species = vegetation::species_of_climate(name_of(looked.climate.koppen));
  return rules;
}

vegetation::TreeOptions plant_look(const Recipe& looked) {
  const bool winter = season_of(looked) == Season::winter;
  const bool snowing = looked.weather.weather == Weather::snow;
  const look::Land lines = look::with_fallbacks(looked.render).land;
  const bool snow_in_forest = look::snow_line_fraction(lines) <= look::tree_line_fraction(lines);
  return {season_of(looked), winter && (snowing || snow_in_forest), vegetation::Detail::full};
}

vegetation::Placement place_scene_plants(const Recipe& looked, const Heightfield& heights, const Context& context) {
  if (!looked.vegetation.enabled) return {};
  return vegetation::place_plants(heights, looked.vegetation, placement_rules(looked, heights), context);
}

namespace {

/// The [tree] plant as the renderer places it among `species`: the seed picks one of the
/// species' shapes.
vegetation::Instance lone_plant(const Recipe& recipe, const std::vector<vegetation::Species>& species) {
  const auto found = std::find_if(species.begin(), species.end(), [&](const auto& s) { return s.name == recipe.tree.species; });
  if (found == species.end()) {
    std::string names;
    for (const auto& s : species) names += (names.empty() ? "" : ", ") + s.name;
    fail("[tree] species '{}' is not known: it must be one of {}", recipe.tree.species, names);
  }
  vegetation::Instance plant;
  plant.species = static_cast<std::uint16_t>(found - species.begin());
  plant.variant = static_cast<std::uint16_t>(recipe.tree.seed % vegetation::variants_per_species);
  return plant;
}

vegetation::TreeOptions lone_look(const Recipe& recipe) {
  return {season_of(recipe), recipe.tree.snow && season_of(recipe) == Season::winter, vegetation::Detail::full};
}

}  // namespace

vegetation::Placement plants_to_draw(const Recipe& looked, const Heightfield& heights, const Context& context) {
  const double width = (heights.width() - 1) * heights.cell_size_m, depth = (heights.height() - 1) * heights.cell_size_m;
  const double spacing = looked.vegetation.ground_spacing_m;
  if (width * depth / (spacing * spacing) <= max_drawn_ground_cells) return place_scene_plants(looked, heights, context);
  Recipe trees_only = looked;
  trees_only.vegetation.ground_density = 0.0;
  return place_scene_plants(trees_only, heights, context);
}

std::string plants_key(const Recipe& looked) {
  const look::RenderParams& r = looked.render;
  const look::Land lines = look::with_fallbacks(r).land;
  return fmt::format("plants {}|{}|{}|{}|lines {},{},{}|sea {},{}", params::text_of(looked.vegetation), params::text_of(looked.climate),
                     params::text_of(looked.season), params::text_of(looked.weather), static_cast<int>(lines.lines),
                     look::tree_line_fraction(lines), look::snow_line_fraction(lines), r.sea, r.sea_level_m);
}

io::PlantCatalogue plant_catalogue() {
  io::PlantCatalogue catalogue;
  for (const vegetation::Species& species : vegetation::species_library()) catalogue.species.push_back(species.name);
  catalogue.variants = vegetation::variants_per_species;
  return catalogue;
}

void write_plant_instances(const std::filesystem::path& path, const vegetation::Placement& placement,
                           const std::optional<nlohmann::json>& provenance) {
  io::write_plant_instances(path, placement.trees, placement.ground, plant_catalogue(), provenance);
}

vegetation::Placement read_plant_instances(const std::filesystem::path& path) {
  io::PlantLayers layers = io::read_plant_instances(path, plant_catalogue());
  vegetation::Placement placement;
  placement.trees = std::move(layers.trees);
  placement.ground = std::move(layers.ground);
  return placement;
}

std::vector<vegetation::Species> tree_species(const Recipe& recipe) {
  std::vector<vegetation::Species> species = vegetation::species_library();
  if (recipe.tree.species_file.empty()) return species;
  const std::filesystem::path file = detail::resolve(recipe, recipe.tree.species_file);
  for (vegetation::Species& own : vegetation::read_species_file(io::read_text_file(file, std::size_t{1} << 20), file.string())) {
    const auto same = std::find_if(species.begin(), species.end(), [&](const auto& s) { return s.name == own.name; });
    if (same != species.end())
      *same = std::move(own);
    else
      species.push_back(std::move(own));
  }
  return species;
}

void check_tree_species(const Recipe& recipe) {
  (void)lone_plant(recipe, tree_species(recipe));
}

TriangleMesh tree_mesh_of(const Recipe& recipe) {
  const std::vector<vegetation::Species> species = tree_species(recipe);
  const vegetation::Instance plant = lone_plant(recipe, species);
  return vegetation::build_tree(species[plant.species], vegetation::variant_seed(plant.species, plant.variant), lone_look(recipe));
}

Image tree_picture(const Recipe& recipe, const Context& context) {
  const std::vector<vegetation::Species> library = tree_species(recipe);
  const vegetation::Instance lone = lone_plant(recipe, library);
  const vegetation::Species& species = library[lone.species];
  // A flat patch of ground a little wider than the plant is tall or wide, the plant at its centre;
  // the sea a hair below it, so that the block under the ground stays thin.
  double reach = 0.0;
  for (const glm::vec3& p :
       vegetation::build_tree(species, vegetation::variant_seed(lone.species, lone.variant), lone_look(recipe)).positions)
    reach = std::max({reach, std::abs(double{p.x}), std::abs(double{p.z})});
  const double size_m = 1.3 * std::max(species.height_m, 2.0 * reach);
  // Plain ground: a single cell. The terrain's colour noise repeats a whole number of times
  // over any terrain's extent, so its four corners read the same value; finer ground samples
  // it far below its period and shows a checkerboard (issue 31).
  constexpr int samples = 2;
  Heightfield ground(samples, samples, 0.0f, size_m / (samples - 1));
  Recipe looked = recipe;
  looked.render.sea = true;
  looked.render.sea_level_m = -0.02 * size_m;
  looked.render.shadows = false;  // the terrain's horizon shadows; a flat patch has none
  resolve_look(looked);
  // Flat ground is the forest floor in every band (the bands would make it the highest peak:
  // snow), under snow in a snowy winter; the camera looks at the plant from low down.
  const Rgb floor = lone_look(recipe).snow ? *looked.render.land.snow : *looked.render.land.forest_low;
  for (auto* colour : {&looked.render.land.beach, &looked.render.land.forest_low, &looked.render.land.forest_high,
                       &looked.render.land.cliff, &looked.render.land.snow})
    *colour = floor;
  looked.render.camera.elevation_deg = 12.0;
  vegetation::Placement placement;
  placement.species = &library;
  vegetation::Instance plant = lone;
  plant.x_m = plant.y_m = static_cast<float>(size_m / 2.0);
  placement.trees.push_back(plant);
  look::TerrainLayers layers;
  look::PlantKindCache kinds;
  layers.plants = kinds.plants_to_draw(placement, lone_look(recipe));
  return paint(ground, looked.render, layers, context);
}

}  // namespace sansui::scene

#include "scene/plants.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
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

namespace {

/// The samples of `heights` within `reach_m` of the point at fractions (fx, fy) of its extent
/// (x east, y south), with the origin of their place in the world: placement there gives the
/// plants the whole heightfield would (vegetation::place_plants keys them by world position).
Heightfield window_around(const Heightfield& heights, double fx, double fy, double reach_m) {
  const double cell = heights.cell_size_m;
  const auto span = [&](double fraction, int samples, int& first, int& last) {
    const double centre = std::clamp(fraction, 0.0, 1.0) * (samples - 1);
    first = std::clamp(static_cast<int>(std::floor(centre - reach_m / cell)), 0, samples - 1);
    last = std::clamp(static_cast<int>(std::ceil(centre + reach_m / cell)), first, samples - 1);
  };
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  span(fx, heights.width(), x0, x1);
  span(fy, heights.height(), y0, y1);
  Heightfield window = Heightfield::uninitialized(x1 - x0 + 1, y1 - y0 + 1, cell);
  window.origin_x_m = heights.origin_x_m + x0 * cell;
  window.origin_y_m = heights.origin_y_m + y0 * cell;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) window(x - x0, y - y0) = heights(x, y);
  return window;
}

/// Where a camera near the ground stands (fractions of the terrain's extent) and how far around
/// it its picture shows ground plants; nullopt for a camera high above the ground.
struct NearGround {
  double fx = 0.5, fy = 0.5, reach_m = ground_plants_reach_m;
};
std::optional<NearGround> near_ground(const look::Camera& camera, const Heightfield& heights) {
  const double width_m = (heights.width() - 1) * heights.cell_size_m, depth_m = (heights.height() - 1) * heights.cell_size_m;
  NearGround near{camera.target_x, camera.target_y};
  if (camera.eye_height_m) return *camera.eye_height_m <= ground_plants_eye_height_m ? std::optional(near) : std::nullopt;
  if (camera.distance <= 0.0) return std::nullopt;  // fitted: the whole terrain from afar
  // An orbiting camera: its bearing from the target, clockwise from north (look/camera.cpp).
  const double distance_m = camera.distance * std::max(width_m, depth_m), pi = std::numbers::pi;
  const double level_m = distance_m * std::cos(camera.elevation_deg * pi / 180.0);
  if (distance_m * std::sin(camera.elevation_deg * pi / 180.0) > ground_plants_eye_height_m) return std::nullopt;
  const double azimuth = camera.azimuth_deg * pi / 180.0;
  near.fx += std::sin(azimuth) * level_m / std::max(width_m, 1e-9);
  near.fy -= std::cos(azimuth) * level_m / std::max(depth_m, 1e-9);
  near.reach_m = std::max(near.reach_m, 1.5 * level_m);
  return near;
}

}  // namespace

vegetation::Placement plants_for_picture(const Recipe& looked, const Heightfield& heights, const Context& context) {
  vegetation::Placement placement = plants_to_draw(looked, heights, context);
  const std::optional<NearGround> near = near_ground(looked.render.camera, heights);
  if (!placement.ground.empty() || !looked.vegetation.enabled || !near) return placement;
  // The ground layer alone, by the rules of the whole terrain (its tree line, its sea).
  vegetation::PlacementRules rules = placement_rules(looked, heights);
  rules.tree_density = 0.0;
  vegetation::VegetationParams ground_only = looked.vegetation;
  ground_only.density = 0.0;
  const Heightfield window = window_around(heights, near->fx, near->fy, near->reach_m);
  placement.ground = vegetation::place_plants(window, ground_only, rules, context).ground;
  return placement;
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

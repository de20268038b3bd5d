#include "scene/scenery.hpp"

#include <algorithm>

#include "look/surface_layers.hpp"
#include "scene/look.hpp"
#include "scene/pipeline.hpp"
#include "scene/plants.hpp"
#include "scene/scene_parts.hpp"
#include "scene/water_layers.hpp"

namespace sansui::scene {
namespace {

/// The outputs whose sections make a scene's look: what the scene's parts are made like.
bool makes_scenery(OutputKind kind) {
  return kind == OutputKind::render || kind == OutputKind::mesh || kind == OutputKind::splat_map || kind == OutputKind::plants ||
         kind == OutputKind::tree;
}

/// The recipe as its outputs read it: the world's facts handed on, then the look resolved.
Recipe looked_recipe(const Recipe& recipe) {
  Recipe looked = recipe;
  settle_world(looked);
  if (looked.base_dir.empty()) looked.base_dir = std::filesystem::current_path();
  resolve_look(looked);
  return looked;
}

void add_layer(std::vector<SceneryPlant>& out, const std::vector<vegetation::Instance>& layer, const Heightfield& heights,
               std::uint8_t layer_index) {
  for (const vegetation::Instance& plant : layer) {
    SceneryPlant p;
    p.x_m = static_cast<float>(plant.x_m - heights.origin_x_m);
    p.y_m = static_cast<float>(0.0 - (plant.y_m - heights.origin_y_m));
    p.z_m = plant.height_m;
    p.scale = plant.scale;
    p.rotation_rad = plant.rotation_rad;
    p.species = plant.species;
    p.variant = plant.variant;
    p.layer = layer_index;
    out.push_back(p);
  }
}

}  // namespace

std::vector<const scene::Section*> scenery_sections() {
  std::vector<const scene::Section*> sections;
  for (const scene::Section& section : recipe_sections())
    if (std::any_of(section.outputs.begin(), section.outputs.end(), makes_scenery)) sections.push_back(&section);
  return sections;
}

std::vector<SceneryPlant> scenery_plants(const vegetation::Placement& placement, const Heightfield& heights) {
  std::vector<SceneryPlant> plants;
  plants.reserve(placement.trees.size() + placement.ground.size());
  add_layer(plants, placement.trees, heights, 0);
  add_layer(plants, placement.ground, heights, 1);
  return plants;
}

Grid<float> water_depth(const Heightfield& heights, const Grid<float>& surface_depth_m, bool sea, double sea_level_m) {
  Grid<float> depth(heights.width(), heights.height(), 0.0f, heights.cell_size_m);
  depth.copy_metadata_from(heights);
  const bool rivers = !surface_depth_m.empty();
  for (std::size_t i = 0; i < depth.size(); ++i) {
    float d = rivers ? surface_depth_m.values()[i] : 0.0f;
    if (sea) d = std::max(d, static_cast<float>(sea_level_m - heights.values()[i]));
    depth.values()[i] = d;
  }
  return depth;
}

Scenery make_scenery(const Recipe& recipe, const Context& context) {
  const Recipe looked = looked_recipe(recipe);
  Scenery scenery;
  scenery.heights = recipe_heights(recipe, context);
  const Heightfield& heights = scenery.heights;
  const look::RenderParams resolved = look::with_fallbacks(looked.render);
  scenery.sea = resolved.sea;
  scenery.sea_level_m = look::effective_sea_level(resolved, heights);
  scenery.origin = {heights.origin_x_m, 0.0 - heights.origin_y_m};  // 0 - y: north 0 is +0, not -0

  // The ground: the mesh outputs' band colours and the splat map output's weights.
  context.report("scenery", 0.0);
  scenery.colour = look::band_colour_map(heights, resolved, std::max(heights.width(), heights.height()));
  scenery.splat = look::splat_weights_image(look::surface_weights(heights, resolved));
  context.report("scenery", 0.5);
  context.check_cancelled();

  // Water and plants as the viewer draws them.
  const std::shared_ptr<const SurfaceWater> surface = scene_water(looked, heights, {}, context);
  scenery.water_m = water_depth(heights, surface->depth_m, scenery.sea, scenery.sea_level_m);
  const std::shared_ptr<const vegetation::Placement> placement = scene_plants(looked, heights, surface.get(), {}, context);
  scenery.plants = scenery_plants(*placement, heights);
  for (const vegetation::Species& species : placement->library()) scenery.species.push_back(species.name);
  scenery.season = season_of(looked);
  scenery.plant_snow = plant_look(looked).snow;
  context.report("scenery", 1.0);
  return scenery;
}

}  // namespace sansui::scene

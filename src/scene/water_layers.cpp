#include "scene/water_layers.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/params_text.hpp"

namespace sansui::scene {

bool draws_surface_water(const Recipe& recipe) {
  if (recipe.render.rivers) return *recipe.render.rivers;
  // An eroded land has rivers and lakes, whether a [[shape]] step or an erode node wore it.
  return std::ranges::any_of(recipe.shape, [](const ShapeStep& step) { return step.step == StepKind::erode; }) ||
         std::ranges::any_of(recipe.nodes, [](const GraphNode& node) { return node.kind == "erode"; });
}

water::FlowParams flow_params(const Recipe& recipe) {
  water::FlowParams flow = recipe.flow;
  if (!flow.sea_level_m && recipe.render.sea) flow.sea_level_m = recipe.render.sea_level_m;
  return flow;
}

water::SurfaceWater scene_surface_water(const Recipe& recipe, const Heightfield& heights, const Context& context) {
  return water::surface_water(heights, flow_params(recipe), context);
}

std::string surface_water_key(const Recipe& recipe) {
  return fmt::format("water {}|{}", draws_surface_water(recipe), params::text_of(flow_params(recipe)));
}

void remove_plants_in_water(vegetation::Placement& plants, const water::SurfaceWater& water) {
  const Grid<float>& depth = water.depth_m;
  if (depth.empty()) return;
  auto wet = [&](const vegetation::Instance& plant) {
    const long x = std::lround((plant.x_m - depth.origin_x_m) / depth.cell_size_m);
    const long y = std::lround((plant.y_m - depth.origin_y_m) / depth.cell_size_m);
    return x >= 0 && y >= 0 && x < depth.width() && y < depth.height() && depth(static_cast<int>(x), static_cast<int>(y)) > 0.0f;
  };
  std::erase_if(plants.trees, wet);
  std::erase_if(plants.ground, wet);
}

Grid<float> splat_map(OutputKind kind, const water::SurfaceWater& water, const Grid<float>* eroded, const Grid<float>* deposited) {
  switch (kind) {
    case OutputKind::flow_map: {
      Grid<float> map(water.area_m2.width(), water.area_m2.height(), 0.0f);
      water::copy_placement(map, water.area_m2);
      for (std::size_t i = 0; i < map.size(); ++i)
        map.values()[i] = static_cast<float>(std::log10(std::max(water.area_m2.values()[i], 1.0)));
      return map;
    }
    case OutputKind::erosion_map:
    case OutputKind::deposition_map: {
      const Grid<float>* map = kind == OutputKind::erosion_map ? eroded : deposited;
      if (map == nullptr) fail("an {} needs an erode step: add [[shape]] step = \"erode\" (or --erode)", output_kind_name(kind));
      return *map;
    }
    case OutputKind::wetness_map:
      return water.wetness;
    case OutputKind::water_depth_map:
      return water.depth_m;
    default:
      break;
  }
  fail("{} is not a splat map", output_kind_name(kind));
}

}  // namespace sansui::scene

#include "scene/water_layers.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.hpp"
#include "core/parallel.hpp"
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

namespace {

/// The routing given, where it was made on `heights` (their place too) with `params`' outlets.
const water::FlowRouting* routing_to_take(const RoutedHeights* given, const Heightfield& heights, const water::FlowParams& params) {
  if (given == nullptr || given->flow == nullptr || params.outlets().sea_level_m != given->sea_level_m) return nullptr;
  const Heightfield& routed = given->flow->surface;
  const bool same_place = routed.width() == heights.width() && routed.height() == heights.height() &&
                          routed.cell_size_m == heights.cell_size_m && routed.origin_x_m == heights.origin_x_m &&
                          routed.origin_y_m == heights.origin_y_m;
  return same_place ? given->flow.get() : nullptr;
}

}  // namespace

water::SurfaceWater scene_surface_water(const Recipe& recipe, const Heightfield& heights, const Context& context,
                                        const RoutedHeights* routing_of_heights) {
  const water::FlowParams params = flow_params(recipe);
  return water::surface_water(heights, params, context, routing_to_take(routing_of_heights, heights, params));
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

Grid<double> scene_drainage_area(const Recipe& recipe, const Heightfield& heights, const Context& context,
                                 const RoutedHeights* routing_of_heights) {
  const water::FlowParams params = flow_params(recipe);
  params.validate();
  if (const water::FlowRouting* routed = routing_to_take(routing_of_heights, heights, params)) return routed->area_m2;
  return water::route_flow(heights, params.outlets(), context).area_m2;
}

Grid<float> flow_map(const Grid<double>& area_m2) {
  Grid<float> map(area_m2.width(), area_m2.height(), 0.0f);
  water::copy_placement(map, area_m2);
  parallel_for_ranges<std::size_t>(0, map.size(), 1 << 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) map.values()[i] = static_cast<float>(std::log10(std::max(area_m2.values()[i], 1.0)));
  });
  return map;
}

}  // namespace sansui::scene

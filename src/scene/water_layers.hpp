// Rivers, lakes and the erosion maps of a recipe: what render outputs (and the viewer) draw over
// the land and what the rivers, lakes and splat-map outputs write.
#pragma once

#include <memory>
#include <optional>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "scene/recipe.hpp"
#include "vegetation/placement.hpp"
#include "water/surface_water.hpp"

namespace sansui::scene {

/// A scene's rivers and lakes (water depth, wetness, the surface lakes lie at): the engine's
/// product that the viewer holds, by the scene's name for it.
using SurfaceWater = water::SurfaceWater;

/// A routing of some heights made before (a graph's flow node's), with the sea level of its
/// outlets: the outputs take it where it is of their heights and their outlets.
struct RoutedHeights {
  std::shared_ptr<const water::FlowRouting> flow;
  std::optional<double> sea_level_m;
};

/// True when the recipe's pictures show rivers and lakes: render.draw_water, or unset, when the
/// heightfield went through an erode step (raw fractal terrain has pits everywhere, which
/// would all be lakes).
bool draws_surface_water(const Recipe& recipe);

/// The recipe's [flow] with its base level settled: the world's sea level (settle_world), [flow] sea_level
/// in recipes before version 3, or else the sea the picture
/// draws (render.sea_level when render.sea is on).
water::FlowParams flow_params(const Recipe& recipe);

/// Rivers, lakes and wetness of the recipe's heights.
/// `routing_of_heights`: as water::surface_water's (taken only where its outlets are the recipe's).
water::SurfaceWater scene_surface_water(const Recipe& recipe, const Heightfield& heights, const Context& context = quiet_context(),
                                        const RoutedHeights* routing_of_heights = nullptr);

/// What scene_surface_water() reads of the recipe, and whether the scene draws its water, as text.
std::string surface_water_key(const Recipe& recipe);

/// Plants standing in a river or lake are taken out (trees do not grow in water; the lake's
/// surface would hold them up).
void remove_plants_in_water(vegetation::Placement& plants, const water::SurfaceWater& water);

/// The D8 drainage area of `heights` over its depressions, as scene_surface_water() has it, without
/// its lakes, rivers and wetness. [Units: m^2]
Grid<double> scene_drainage_area(const Recipe& recipe, const Heightfield& heights, const Context& context = quiet_context(),
                                 const RoutedHeights* routing_of_heights = nullptr);

/// A flow_map output: log10 of the drainage area in m^2 (of at least 1 m^2).
Grid<float> flow_map(const Grid<double>& area_m2);

}  // namespace sansui::scene

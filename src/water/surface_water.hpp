// Rivers and lakes as the renderer and engines take them: per cell, the depth of water standing
// on the ground and how wet the ground is. Lakes are the depressions priority-flood keeps
// (filled to their spill level); rivers are the channels of D8 routing, as wide and deep as
// their discharge makes them (Leopold & Maddock's hydraulic geometry, "The hydraulic geometry of
// stream channels", USGS PP 252, 1953: width = 2.7 Q^0.5, depth = 0.3 Q^0.4, metres for Q in
// m^3/s, middle values of their rivers); wetness is the topographic wetness index
// ln(a / tan(slope)) (Beven & Kirkby 1979) scaled between its 70th and 99th percentiles, and
// 1 under water.
#pragma once

#include "core/context.hpp"
#include "core/grid.hpp"
#include "water/flow.hpp"
#include "water/priority_flood.hpp"
#include "water/rivers.hpp"

namespace sansui::water {

/// Depressions of fewer cells are puddles, not lakes (droplet erosion leaves thousands).
inline constexpr std::int64_t min_lake_cells = 16;

struct SurfaceWater {
  Heightfield surface;   ///< the ground with lakes filled to their level: draw this, lakes are flat. [Units: m]
  Grid<float> depth_m;   ///< water over the ground: lake depth, or a river's depth where its bed is. [Units: m]
  Grid<float> wetness;   ///< 0 dry .. 1 wet (under water, or where water gathers)
  Grid<double> area_m2;  ///< D8 drainage area on the filled surface. [Units: m^2]
  RiverNetwork rivers;
  LakeFill lakes;  ///< lakes of at least min_lake_cells cells; smaller pits are dry in `surface`
};

/// Lakes, rivers and wetness of `heights` (the sea, below params.sea_level_m, is not included:
/// the renderer draws it). Deterministic; the same bytes with any number of threads.
/// `routing_of_heights`: route_flow's routing of exactly these heights with params.outlets(),
/// made before (a graph's flow node); null: routed here.
SurfaceWater surface_water(const Heightfield& heights, const FlowParams& params, const Context& context = quiet_context(),
                           const FlowRouting* routing_of_heights = nullptr);

/// Leopold & Maddock's width and depth of a river carrying `discharge_m3_per_s`. [Units: m]
double river_width_m(double discharge_m3_per_s);
double river_depth_m(double discharge_m3_per_s);

}  // namespace sansui::water

// The default erosion chain: stream power (valleys at the landscape scale), thermal erosion
// (screes below steep faces, hillslopes held at their angle of repose), then droplets (rills and
// small fans), and the land's fine roughness kept on its hillslopes.
//
// Four models, chosen by the recipe's version:
//   1 (recipes of version 1): stream power for all its steps, then every thermal iteration, then
//     the droplets; the map's edge is fixed base level.
//   2 (recipes of versions 2 to 5): each stream-power step is followed by its share of the thermal
//     iterations (hillslopes keep up with the rivers cutting below them); the map's edge follows
//     the land inside it (it is where water leaves, not a wall that stands while everything else
//     wears down); droplets end at base level; and the fine roughness of the land before erosion
//     (wavelengths under 2^detail_levels cells) is put back on its hillslopes, weighted by
//     keep_detail, fading out where rivers cut deep and on the plains at base level. Diffusion
//     and droplets smooth that roughness away, which leaves eroded land smoother than any real
//     land at small scales (its spectral exponent above 3.6, water/landform.hpp).
//   3 (recipes of version 6): model 2, but what is put back is the fine roughness
//     the erosion took away (the roughness before, less what is left of it), not the whole of it
//     again: land that little erosion touched (the stages original and young) keeps the
//     roughness it had, where model 2 doubled it (18.6 % of the land steeper than 45 degrees
//     after `original`, against 3.5 % before).
//   4 (recipes of version 7 on, the default): model 3 on the map with a margin of land past its
//     edges (edge_margin.hpp), so that water crosses the map's edges both ways: the strip along
//     each edge erodes as the land inside does, where model 3 left it standing as a rim that
//     ends in a scarp.
#pragma once

#include <optional>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "water/droplets.hpp"
#include "water/stream_power.hpp"
#include "water/thermal.hpp"

namespace sansui::water {

struct ErosionChainParams {
  StreamPowerParams fluvial;
  ThermalParams thermal;
  DropletParams droplets;
  /// Model 2: how much of the land's fine roughness its hillslopes keep (0: the smooth eroded
  /// surface; 1: as rough as before). [Range: 0..2] [Default: 1; recipes of version 1: 0]
  double keep_detail = 1.0;
};

/// The wavelengths kept by keep_detail: under 2^detail_levels cells.
inline constexpr int detail_levels = 3;

/// The model of recipes of this version (see above).
inline constexpr int default_erosion_model = 4;

/// The three stages in turn, as `model` says (1 to 4); eroded_m and deposited_m are the
/// stream-power stage's maps, and the budget is its budget. A stage with zero steps, iterations
/// or droplets is skipped. Model 2 takes fluvial.sea_level_m as the base level of droplets too.
/// `stage`: the erosion lasts that stage of Davis's cycle (params_for_stage: the time step and an
/// unset diffusivity from the heights' response time); nullopt: params.fluvial's own time step.
/// Models 2 and 3 route the heights once for the response time and its first step, or take
/// `routing_of_heights`: route_flow's routing of exactly these heights under
/// params.fluvial.sea_level_m, made before (a graph's flow node). Models 1 and 4 route anew.
ErosionResult erode(const Heightfield& heights, const ErosionChainParams& params, std::optional<ErosionStage> stage, const Context& context,
                    int model = default_erosion_model, const FlowRouting* routing_of_heights = nullptr);
/// erode() for params.fluvial's own time step.
ErosionResult erode(const Heightfield& heights, const ErosionChainParams& params, const Context& context = quiet_context(),
                    int model = default_erosion_model);

/// Seconds erode() takes about on `cells` cells on the reference machine (2 cores, Release
/// build), from the rates bench_water measures: for a warning before long work, for the work
/// limit, and to weight the parts of the erosion's progress so that its remaining time is honest.
/// `staged`: the time step from a stage (erode's `stage`), whose response time routes first.
double estimated_erosion_seconds(std::size_t cells, const ErosionChainParams& params, bool staged = false);
/// Seconds one routing of `cells` cells takes about (the response time's), as above.
double estimated_routing_seconds(std::size_t cells);

/// The part of `heights` at wavelengths under 2^levels cells: heights minus their bilinear
/// interpolation from every 2^levels-th sample (grids smaller than that: all zero).
Grid<float> fine_detail(const Heightfield& heights, int levels);

}  // namespace sansui::water

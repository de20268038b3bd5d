// Flow routing on a heightfield: D8 receivers (O'Callaghan & Mark 1984: steepest descent to one
// of eight neighbours), the receiver stack of Braun & Willett ("A very efficient O(n), implicit
// and parallel method to solve the stream power equation governing fluvial incision and
// landscape evolution", Geomorphology 180, 2013), D8 drainage area, multiple-flow-direction
// area (Freeman, "Calculating catchment area with divergent flow based on a regular grid",
// Computers & Geosciences 17, 1991) and watershed labels.
//
// Cells are indices y * width + x. Outlets (the map's edge, cells at or below the sea) are their own
// receivers: water and sediment leave the map there.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "core/params.hpp"
#include "water/neighbours.hpp"
#include "water/priority_flood.hpp"
#include "water/routing_scratch.hpp"

namespace sansui::water {

/// Flow routing and river extraction. Table: water_params.cpp (section [flow]).
struct FlowParams {
  /// Cells below this height are sea: outlets. Unset: only the map's edge drains. [Units: m]
  std::optional<double> sea_level_m;
  /// Drainage area at which a channel begins. [Units: m^2] [Range: > 0] [Default: 1e6]
  double channel_area_m2 = 1e6;
  /// Runoff, for discharge = drainage area x runoff. [Units: mm/yr] [Range: >= 0] [Default: 500]
  double runoff_mm_per_yr = 500.0;
  /// Freeman's exponent p of multiple-flow-direction routing. [Range: > 0] [Default: 1.1]
  double flow_exponent = 1.1;

  Outlets outlets() const { return {sea_level_m}; }
  /// Throws InputError naming the first bad value.
  void validate() const;
};
const params::Table<FlowParams>& parameter_table(const FlowParams*);

/// The D8 receiver of every cell on `surface`: the neighbour of steepest descent (the first in
/// neighbours.hpp's order on a tie), or the cell itself at an outlet or a pit.
Grid<CellIndex> d8_receivers(const Heightfield& surface, const Outlets& outlets);
/// The same into `receiver`, reshaped as needed.
void d8_receivers(const Heightfield& surface, const Outlets& outlets, Grid<CellIndex>& receiver);

/// Every cell once, each receiver before its donors (Braun & Willett's stack, built depth first
/// from the cells that are their own receivers, in raster order: each drainage tree is one run).
/// Walk it backwards to go downstream.
std::vector<CellIndex> receiver_stack(const Grid<CellIndex>& receiver);
/// The same into `stack`, built in parallel (the trees rooted in each block of rows on their own,
/// then joined in raster order: the same stack with any number of threads).
void receiver_stack(const Grid<CellIndex>& receiver, std::vector<CellIndex>& stack, RoutingScratch& scratch);

/// Bounds of about `pieces` runs of the stack, each holding whole drainage trees: walks along
/// the stack can take the runs in parallel. bounds[0] = 0, bounds.back() = stack.size(). The
/// bounds depend only on the stack, never on the number of threads.
std::vector<std::size_t> stack_pieces(const std::vector<CellIndex>& stack, const Grid<CellIndex>& receiver, std::size_t pieces = 64);

/// D8 drainage area: each cell's own area plus the area of all cells that drain through it.
Grid<double> d8_drainage_area(const Grid<CellIndex>& receiver, const std::vector<CellIndex>& stack, double cell_size_m);
/// The same into `area`, reshaped as needed.
void d8_drainage_area(const Grid<CellIndex>& receiver, const std::vector<CellIndex>& stack, double cell_size_m, Grid<double>& area);

/// Multiple-flow-direction drainage area (Freeman 1991): each cell passes its area to all lower
/// neighbours in proportion to tan(slope)^exponent. `surface` must drain everywhere (the output
/// of fill_depressions_epsilon); outlets keep what they receive. [Units: m^2]
Grid<double> mfd_drainage_area(const Heightfield& surface, const Outlets& outlets, double exponent);

/// Watershed labels: 1 + the number of the outlet (in raster order) each cell drains to.
Grid<std::int32_t> basin_labels(const Grid<CellIndex>& receiver, const std::vector<CellIndex>& stack);

/// The whole routing of a heightfield: receivers across depressions, stack, D8 area.
struct FlowRouting {
  Heightfield surface;           ///< the ground with depressions filled to their spill level (lakes). [Units: m]
  Grid<CellIndex> receiver;      ///< D8 receiver of every cell
  std::vector<CellIndex> stack;  ///< receivers before donors
  Grid<double> area_m2;          ///< D8 drainage area. [Units: m^2]
};

/// Routes the flow over `heights`: D8 receivers with every depression drained over its lowest pass
/// (depression_routing.hpp), stack, accumulation.
FlowRouting route_flow(const Heightfield& heights, const Outlets& outlets, const Context& context = quiet_context());
/// The same into `flow`, keeping its memory and the working memory in `scratch` between calls (the
/// steps of an erosion run allocate once).
void route_flow(const Heightfield& heights, const Outlets& outlets, FlowRouting& flow, RoutingScratch& scratch,
                const Context& context = quiet_context());

}  // namespace sansui::water

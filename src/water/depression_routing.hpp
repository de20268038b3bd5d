// Routing across depressions without a priority queue over every cell: Cordonnier, Bovy & Braun,
// "A versatile, linear complexity algorithm for flow routing in topographies with depressions",
// Earth Surface Dynamics 7 (2019), the method of FastScape.
//
// D8 receivers are taken on the ground as it is; every pit (a cell with no lower neighbour that
// is not an outlet) roots a basin. Basins are joined by their lowest passes (a minimum spanning
// tree of the basin graph, Kruskal's algorithm over the cell pairs that cross basin borders, the
// pass height being the higher cell of the pair), and each pit is made to drain over its pass by
// reversing the receivers from the pass down to the pit ("carving"). The water level of a basin is
// the highest pass on its way to an outlet: exactly the spill level a priority-flood fills to.
#pragma once

#include <cstdint>

#include "core/context.hpp"
#include "core/grid.hpp"
#include "water/neighbours.hpp"
#include "water/priority_flood.hpp"
#include "water/routing_scratch.hpp"

namespace sansui::water {

/// Receivers that bring every cell to an outlet, and the lake levels of the depressions.
struct DepressionRouting {
  Grid<CellIndex> receiver;      ///< each cell's downstream neighbour; outlets are their own
  Heightfield water_level;       ///< the spill level over a depression, the ground elsewhere. [Units: m]
  std::int64_t depressions = 0;  ///< number of pits (basins not draining to an outlet)
};

/// Routes `heights` across its depressions (see the file comment). Deterministic: the spanning
/// tree is ordered by (pass height, cell pair), the same with any number of threads.
DepressionRouting route_depressions(const Heightfield& heights, const Outlets& outlets, const Context& context = quiet_context());

/// The same into `receiver` and `water_level` (reshaped as needed), with working memory kept in
/// `scratch` between calls: for the steps of an erosion run. Returns the number of depressions.
std::int64_t route_depressions(const Heightfield& heights, const Outlets& outlets, Grid<CellIndex>& receiver, Heightfield& water_level,
                               RoutingScratch& scratch, const Context& context = quiet_context());

}  // namespace sansui::water

// Depression handling by priority-flood: Barnes, Lehman & Mulla, "Priority-Flood: An optimal
// depression-filling and watershed-labeling algorithm for digital elevation models", Computers &
// Geosciences 62 (2014), Algorithms 2 (improved, with a plain queue for pit cells) and 3 (+epsilon).
//
// The flood starts from the outlets: every cell of the map's edge, and every cell at or below the sea
// level when one is given. Cells leave a monotone radix heap in order of (level, insertion
// counter), so ties are broken the same way on every run; cells at or below the current level
// skip the heap through a FIFO queue, which is what makes the flood fast on real terrain.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/context.hpp"
#include "core/grid.hpp"

namespace sansui::water {

/// Which cells are outlets (water leaves the map there): the edge, and cells of the sea.
struct Outlets {
  /// Cells at or below this height are sea (or base level, such as a flat plain around a
  /// mountain): outlets, never filled. Unset: only the edge drains.
  std::optional<double> sea_level_m;
};

/// True if cell (x, y) of `heights` is an outlet.
inline bool is_outlet(const Heightfield& heights, const Outlets& outlets, int x, int y) {
  if (x == 0 || y == 0 || x == heights.width() - 1 || y == heights.height() - 1) return true;
  return outlets.sea_level_m && static_cast<double>(heights(x, y)) <= *outlets.sea_level_m;
}

/// Every depression filled so that every cell drains: along filled flats and lake surfaces the
/// height rises by one float step (std::nextafter) per cell away from the spill point, so each
/// cell has a strictly lower neighbour on its way to an outlet. Outlets keep their heights.
Heightfield fill_depressions_epsilon(const Heightfield& heights, const Outlets& outlets, const Context& context = quiet_context());

/// One lake: a connected set of cells (8-neighbours) whose water level is above the ground.
struct Lake {
  float level_m = 0.0f;         ///< water surface (the depression's spill level). [Units: m]
  std::int64_t cells = 0;       ///< number of flooded cells
  std::int32_t first_cell = 0;  ///< its first cell in raster order (index y * width + x)
  double volume_m3 = 0.0;       ///< water volume: sum of depths times the cell area. [Units: m^3]
};

/// Depressions kept as lakes, each filled to its spill level.
struct LakeFill {
  Heightfield surface;      ///< water level where there is a lake, the ground elsewhere. [Units: m]
  Grid<std::int32_t> lake;  ///< 0 on dry land, k + 1 on a cell of lakes[k]
  std::vector<Lake> lakes;  ///< numbered in raster order of their first cell
};

/// Fills every depression to its spill level (the exact, minimal fill: the lowest surface with
/// no interior pit) and labels the flooded cells as lakes.
LakeFill fill_depressions_with_lakes(const Heightfield& heights, const Outlets& outlets, const Context& context = quiet_context());

/// The lakes of `heights` under a given water level (a depression fill of them, e.g. a
/// FlowRouting's surface): flooded cells labelled as lakes.
LakeFill lakes_of(const Heightfield& heights, Heightfield water_level);

}  // namespace sansui::water

// River networks from D8 flow routing: channel cells (drainage area above a threshold), Strahler
// order (Strahler, "Quantitative analysis of watershed geomorphology", 1957) and river reaches as
// polylines of cells, each with its order and discharge.
#pragma once

#include <cstdint>
#include <vector>

#include "core/grid.hpp"
#include "water/flow.hpp"

namespace sansui::water {

/// One reach: from a source or a confluence down to the next confluence or an outlet. Its last
/// cell is the first cell of the reach below (or the outlet), so reaches join into lines.
struct River {
  std::vector<CellIndex> cells;     ///< upstream to downstream, indices y * width + x
  int strahler_order = 1;           ///< constant along a reach
  double area_m2 = 0.0;             ///< drainage area at the reach's own last cell (above the confluence). [Units: m^2]
  double discharge_m3_per_s = 0.0;  ///< area x runoff there. [Units: m^3/s]
};

struct RiverNetwork {
  Grid<std::uint8_t> channel;   ///< 1 where the drainage area reaches the threshold
  Grid<std::uint8_t> strahler;  ///< Strahler order of channel cells, 0 elsewhere
  std::vector<River> rivers;    ///< reaches, in raster order of their first cell
};

/// Channels, Strahler orders and reaches of `flow` with params.channel_area_m2 and params.runoff_mm_per_yr.
RiverNetwork extract_rivers(const FlowRouting& flow, const FlowParams& params);

/// A river's discharge where its drainage area is `area_m2`: area x params.runoff_mm_per_yr. [Units: m^3/s]
inline double river_discharge_m3_per_s(double area_m2, const FlowParams& params) {
  const double runoff_m_per_s = params.runoff_mm_per_yr * 1e-3 / (365.25 * 86400.0);
  return area_m2 * runoff_m_per_s;
}

/// East and south position of a cell's sample in metres (the grid's origin and cell size).
inline std::pair<double, double> cell_position_m(const Heightfield& grid, CellIndex cell) {
  const int x = cell % grid.width(), y = cell / grid.width();
  return {grid.origin_x_m + x * grid.cell_size_m, grid.origin_y_m + y * grid.cell_size_m};
}

}  // namespace sansui::water

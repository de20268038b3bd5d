// Flow routing of a world cut into tiles, exactly as route_flow routes it whole: the same
// receivers (depressions carved over their passes), water levels and drainage areas, byte for
// byte, on any tiling and any number of ranks. After Barnes, "Parallel priority-flood depression
// filling for trillion cell DEMs" and "Parallel non-divergent flow accumulation for trillion cell
// DEMs on desktops or clusters" (2016), on Cordonnier et al.'s basin graph (depression_routing.hpp):
//
// 1. Each tile takes D8 receivers on its cells (a one-cell halo holds its neighbours' heights)
//    and labels each cell by where its flow ends inside the tile: an outlet, a pit, or the cell
//    of another tile it flows into.
// 2. The root joins the tiles' border labels into world basins and sends each tile the basins of
//    its halo; each tile then finds the lowest pass between every two basins that meet on its
//    cells.
// 3. The root takes the minimum spanning tree of the basin graph. Its keys (pass height, world
//    cell, direction) are unique, so the tree is the one the untiled Kruskal finds; walked from
//    the outlets it gives every basin its water level and its pass.
// 4. Each tile carves the path from a pass down to its pit; a path that leaves the tile goes on
//    in the next tile in the next round of messages.
// 5. Drainage area is counted in cells (integers, so any order of sums gives the same bytes):
//    each tile counts its own cells, the root passes the counts that leave a tile on to where
//    they enter the next, and each tile adds what enters along its paths.
//
// What the root holds: the tiles' border cells and the basin graph's links (one per pair of
// basins meeting in a tile), not the cells.
#pragma once

#include <cstdint>
#include <vector>

#include "core/grid.hpp"
#include "core/tile_exchange.hpp"
#include "water/priority_flood.hpp"

namespace sansui::water {

/// One tile's part of a tiled routing. Grids cover the tile's own cells (cut.owned(tile)).
struct RoutedTile {
  int tile = 0;
  Heightfield heights;                 ///< in: the haloed rectangle (cut.haloed(tile)), halo filled
  std::vector<std::int64_t> receiver;  ///< out: each cell's receiver, a world index (y * width + x)
  Heightfield water_level;             ///< out: the spill level over a depression, the ground elsewhere. [Units: m]
  Grid<double> area_m2;                ///< out: D8 drainage area. [Units: m^2]
  std::int64_t depressions = 0;        ///< out: pits in the whole world
};

/// Routes this rank's tiles (exchange.my_tiles(cut), in that order). Collective.
void route_tiles(const TileCut& cut, std::vector<RoutedTile>& tiles, const Outlets& outlets, double cell_size_m, TileExchange& exchange);

}  // namespace sansui::water

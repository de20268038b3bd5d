// A whole world cut into tiles, for the tests of tiled algorithms (tiled_routing.hpp and after).
#pragma once

#include <vector>

#include "core/grid.hpp"
#include "core/tile_exchange.hpp"
#include "core/tile_halo.hpp"
#include "water/tiled_routing.hpp"

namespace sansui::water::test {

/// This rank's tiles of `world`, each with only its own cells set, the halo left to exchange_halo.
inline std::vector<RoutedTile> cut_into_tiles(const Heightfield& world, const TileCut& cut, TileExchange& exchange) {
  std::vector<RoutedTile> tiles;
  std::vector<Grid<float>*> grids;
  const std::vector<int> mine = exchange.my_tiles(cut);
  tiles.reserve(mine.size());
  for (int t : mine) {
    const Rect own = cut.owned(t), halo = cut.haloed(t);
    RoutedTile tile;
    tile.tile = t;
    tile.heights = Heightfield(halo.width(), halo.height(), -1e30f, world.cell_size_m);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) tile.heights(x - halo.x0, y - halo.y0) = world(x, y);
    tiles.push_back(std::move(tile));
  }
  for (RoutedTile& tile : tiles) grids.push_back(&tile.heights);
  exchange_halo(cut, mine, grids, exchange);
  return tiles;
}

/// This rank's tiles of `world`, routed by route_tiles.
inline std::vector<RoutedTile> routed_tiles(const Heightfield& world, const TileCut& cut, const Outlets& outlets, TileExchange& exchange) {
  std::vector<RoutedTile> tiles = cut_into_tiles(world, cut, exchange);
  route_tiles(cut, tiles, outlets, world.cell_size_m, exchange);
  return tiles;
}

}  // namespace sansui::water::test

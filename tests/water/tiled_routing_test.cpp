// Tiled flow routing gives route_flow's bytes on any tiling (tiled_routing.hpp).
#include "water/tiled_routing.hpp"

#include <gtest/gtest.h>

#include "tiled_test_util.hpp"
#include "water/flow.hpp"
#include "water_test_util.hpp"

namespace sansui::water {
namespace {

using test::cut_into_tiles;

/// Routes `world` in tiles of `tile` cells and compares every cell with route_flow's.
void expect_tiled_equals_whole(const Heightfield& world, int tile, const Outlets& outlets, const std::string& what) {
  const FlowRouting whole = route_flow(world, outlets);
  const TileCut cut{world.width(), world.height(), tile};
  OneProcess exchange;
  std::vector<RoutedTile> tiles = cut_into_tiles(world, cut, exchange);
  route_tiles(cut, tiles, outlets, world.cell_size_m, exchange);
  std::int64_t differing = 0;
  for (const RoutedTile& t : tiles) {
    const Rect own = cut.owned(t.tile);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) {
        const std::size_t c = static_cast<std::size_t>(y - own.y0) * own.width() + (x - own.x0);
        const bool same = t.receiver[c] == whole.receiver(x, y) && t.water_level(x - own.x0, y - own.y0) == whole.surface(x, y) &&
                          t.area_m2(x - own.x0, y - own.y0) == whole.area_m2(x, y);
        if (!same && differing++ < 3)
          ADD_FAILURE() << what << ": cell " << x << "," << y << " receiver " << t.receiver[c] << " / " << whole.receiver(x, y)
                        << ", water " << t.water_level(x - own.x0, y - own.y0) << " / " << whole.surface(x, y) << ", area "
                        << t.area_m2(x - own.x0, y - own.y0) << " / " << whole.area_m2(x, y);
      }
  }
  EXPECT_EQ(differing, 0) << what;
}

TEST(TiledRouting, AFractalWorldRoutesToTheSameBytesOnEveryTiling) {
  const Heightfield world = test::midpoint_terrain(257, 10.0, 5);
  for (int tile : {256, 128, 64, 32, 16, 7})
    for (bool sea : {false, true}) {
      Outlets outlets;
      if (sea) outlets.sea_level_m = 0.0;
      expect_tiled_equals_whole(world, tile, outlets, "tile " + std::to_string(tile) + (sea ? " with sea" : ""));
    }
}

TEST(TiledRouting, FlatsTiesAndOddShapesRouteToTheSameBytes) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    Heightfield world =
        test::random_heights(9 + static_cast<int>(seed * 7 % 41), 6 + static_cast<int>(seed * 5 % 37), seed, seed % 2 ? 3 : 1000);
    world.cell_size_m = seed % 3 == 0 ? 3.7 : 10.0;  // a cell area no double holds exactly
    Outlets outlets;
    if (seed % 4 == 0) outlets.sea_level_m = 0.5;
    for (int tile : {2, 3, 5, 8})
      expect_tiled_equals_whole(world, tile, outlets, "seed " + std::to_string(seed) + " tile " + std::to_string(tile));
  }
}

TEST(TiledRouting, TheHaloCarriesTheNeighboursCells) {
  const Heightfield world = test::random_heights(23, 17, 9, 1000);
  const TileCut cut{23, 17, 5};
  OneProcess exchange;
  const std::vector<RoutedTile> tiles = cut_into_tiles(world, cut, exchange);
  for (const RoutedTile& t : tiles) {
    const Rect halo = cut.haloed(t.tile);
    for (int y = halo.y0; y < halo.y1; ++y)
      for (int x = halo.x0; x < halo.x1; ++x) ASSERT_EQ(t.heights(x - halo.x0, y - halo.y0), world(x, y)) << x << "," << y;
  }
}

}  // namespace
}  // namespace sansui::water

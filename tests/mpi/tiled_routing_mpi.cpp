// Run under mpirun: routes a fractal world in tiles spread over the ranks and compares every
// cell with route_flow's routing of the whole world (which each rank makes for itself: the
// worlds here are small). Exit 0 when every cell of every tile is the same, byte for byte.
// Usage: tiled_routing_mpi SIZE TILE SEED [SEA_LEVEL]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/tile_halo.hpp"
#include "mpi/mpi_exchange.hpp"
#include "terrain/midpoint.hpp"
#include "water/flow.hpp"
#include "water/tiled_routing.hpp"

using namespace sansui;

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  if (argc < 4) {
    std::fprintf(stderr, "usage: tiled_routing_mpi SIZE TILE SEED [SEA_LEVEL]\n");
    return 2;
  }
  const int size = std::atoi(argv[1]), tile = std::atoi(argv[2]);
  terrain::MidpointParams params;
  params.seed = std::strtoull(argv[3], nullptr, 10);
  params.sigma_m = 300.0;
  Heightfield world = terrain::generate_midpoint(params, size);
  world.cell_size_m = 10.0;
  water::Outlets outlets;
  if (argc > 4) outlets.sea_level_m = std::atof(argv[4]);

  mpi::Exchange exchange;
  const TileCut cut{size, size, tile};
  const std::vector<int> mine = exchange.my_tiles(cut);
  std::vector<water::RoutedTile> tiles(mine.size());
  std::vector<Grid<float>*> grids;
  for (std::size_t k = 0; k < mine.size(); ++k) {
    const Rect own = cut.owned(mine[k]), halo = cut.haloed(mine[k]);
    tiles[k].tile = mine[k];
    tiles[k].heights = Heightfield(halo.width(), halo.height(), 0.0f, world.cell_size_m);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) tiles[k].heights(x - halo.x0, y - halo.y0) = world(x, y);
    grids.push_back(&tiles[k].heights);
  }
  exchange_halo(cut, mine, grids, exchange);
  water::route_tiles(cut, tiles, outlets, world.cell_size_m, exchange);

  const water::FlowRouting whole = water::route_flow(world, outlets);
  std::int64_t differing = 0, cells = 0;
  for (const water::RoutedTile& t : tiles) {
    const Rect own = cut.owned(t.tile);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x, ++cells) {
        const int lx = x - own.x0, ly = y - own.y0;
        if (t.receiver[static_cast<std::size_t>(ly) * own.width() + lx] != whole.receiver(x, y) ||
            t.water_level(lx, ly) != whole.surface(x, y) || t.area_m2(lx, ly) != whole.area_m2(x, y))
          ++differing;
      }
  }
  const std::int64_t all_differing = exchange.sum(differing), all_cells = exchange.sum(cells);
  const std::int64_t sent = exchange.sum(exchange.bytes_sent);
  if (exchange.rank() == 0)
    std::printf("%d ranks, %d tiles of %d cells: %lld of %lld cells differ from the whole world's routing; %lld bytes exchanged\n",
                exchange.ranks(), cut.tiles(), tile, static_cast<long long>(all_differing), static_cast<long long>(all_cells),
                static_cast<long long>(sent));
  return all_differing == 0 && all_cells == static_cast<std::int64_t>(world.size()) ? 0 : 1;
}

// Filling the ring of cells around each tile's own cells from the tiles that own them.
#pragma once

#include <vector>

#include "core/grid.hpp"
#include "core/tile_exchange.hpp"

namespace sansui {

/// The tiles other than t that own cells of t's ring of `ring` cells, in row order.
inline std::vector<int> neighbour_tiles(const TileCut& cut, int t, int ring = 1) {
  std::vector<int> around;
  const Rect r = cut.haloed(t, ring);
  const int first = cut.tile_at(r.x0, r.y0), last = cut.tile_at(r.x1 - 1, r.y1 - 1);
  for (int y = first / cut.tiles_x(); y <= last / cut.tiles_x(); ++y)
    for (int x = first % cut.tiles_x(); x <= last % cut.tiles_x(); ++x)
      if (y * cut.tiles_x() + x != t) around.push_back(y * cut.tiles_x() + x);
  return around;
}

/// grids[k] covers cut.haloed(tiles[k], ring) with its own cells set; fills in the rest from
/// the tiles that own it. Collective.
template <class T>
void exchange_halo(const TileCut& cut, const std::vector<int>& tiles, const std::vector<Grid<T>*>& grids, TileExchange& exchange,
                   int ring = 1) {
  std::vector<TileMessage> outgoing;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Rect mine = cut.owned(tiles[k]), have = cut.haloed(tiles[k], ring);
    for (int n : neighbour_tiles(cut, tiles[k], ring)) {
      const Rect r = cut.haloed(n, ring).intersect(mine);
      if (r.empty()) continue;
      std::vector<T> values;
      values.reserve(static_cast<std::size_t>(r.width()) * r.height());
      for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) values.push_back((*grids[k])(x - have.x0, y - have.y0));
      outgoing.push_back({tiles[k], n, Packer().put(std::vector<int>{r.x0, r.y0, r.x1, r.y1}).put(values).take()});
    }
  }
  const std::vector<TileMessage> incoming = exchange.exchange(std::move(outgoing));
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Rect have = cut.haloed(tiles[k], ring);
    for (const TileMessage* m : addressed_to(incoming, tiles[k])) {
      Unpacker in(m->bytes);
      const std::vector<int> r = in.take<int>();
      const std::vector<T> values = in.take<T>();
      std::size_t v = 0;
      for (int y = r[1]; y < r[3]; ++y)
        for (int x = r[0]; x < r[2]; ++x) (*grids[k])(x - have.x0, y - have.y0) = values[v++];
    }
  }
}

}  // namespace sansui

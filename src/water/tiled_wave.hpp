// Tools of algorithms that run on a world cut into tiles (tiled_routing.hpp, tiled_erosion.hpp):
// receivers over a tile's haloed rectangle, and wavefronts that visit every cell after the cells
// it depends on, across tiles.
#pragma once

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/grid.hpp"
#include "core/parallel.hpp"
#include "core/tile_exchange.hpp"
#include "core/tile_halo.hpp"
#include "water/tiled_routing.hpp"

namespace sansui::water::tiled {

using WorldCell = std::int64_t;

struct CellNumber {
  WorldCell cell;
  double value;
};

/// A tile's cells and receivers as the wavefronts see them: receivers over the haloed rectangle.
class TileCells {
 public:
  TileCells(const TileCut& cut, int tile) : cut_(cut), own_(cut.owned(tile)), halo_(cut.haloed(tile)) {}
  const Rect& own() const { return own_; }
  const Rect& halo() const { return halo_; }
  std::size_t owned_count() const { return static_cast<std::size_t>(own_.width()) * own_.height(); }
  std::size_t haloed_count() const { return static_cast<std::size_t>(halo_.width()) * halo_.height(); }
  std::size_t local(int x, int y) const { return static_cast<std::size_t>(y - own_.y0) * own_.width() + (x - own_.x0); }
  std::size_t haloed(int x, int y) const { return static_cast<std::size_t>(y - halo_.y0) * halo_.width() + (x - halo_.x0); }
  std::size_t haloed(WorldCell i) const { return haloed(cut_.x_of(i), cut_.y_of(i)); }
  bool owns(WorldCell i) const { return own_.contains(cut_.x_of(i), cut_.y_of(i)); }
  const TileCut& cut() const { return cut_; }
  /// Calls f(donor x, donor y) for each cell of the haloed rectangle that drains into (x, y), in
  /// raster order.
  template <class F>
  void for_donors(int x, int y, const Grid<std::int64_t>& receiver, F&& f) const {
    const WorldCell self = cut_.index(x, y);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((dx == 0 && dy == 0) || !halo_.contains(nx, ny)) continue;
        if (receiver(nx - halo_.x0, ny - halo_.y0) == self) f(nx, ny);
      }
  }

 private:
  const TileCut& cut_;
  Rect own_, halo_;
};

/// The receivers of each tile over its haloed rectangle, halo from the neighbouring tiles.
inline std::vector<Grid<std::int64_t>> haloed_receivers(const TileCut& cut, const std::vector<const RoutedTile*>& tiles,
                                                        TileExchange& exchange) {
  std::vector<Grid<std::int64_t>> receivers;
  std::vector<int> ids;
  for (const RoutedTile* t : tiles) {
    const Rect own = cut.owned(t->tile), halo = cut.haloed(t->tile);
    Grid<std::int64_t> r(halo.width(), halo.height(), -1);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x)
        r(x - halo.x0, y - halo.y0) = t->receiver[static_cast<std::size_t>(y - own.y0) * own.width() + (x - own.x0)];
    receivers.push_back(std::move(r));
    ids.push_back(t->tile);
  }
  std::vector<Grid<std::int64_t>*> grids;
  grids.reserve(receivers.size());
  for (auto& r : receivers) grids.push_back(&r);
  exchange_halo(cut, ids, grids, exchange);
  return receivers;
}

/// Which way a wavefront goes: from the outlets up (a cell waits for its receiver), or from the
/// sources down (a cell waits for all its donors).
enum class Wave { outlets_first, sources_first };

/// Runs visit(k, x, y) -> value once on every own cell of every tile k, each after the cells it
/// waits for, across tiles (see the file comment). values[k] covers tile k's haloed rectangle:
/// visit reads its dependencies' values there and returns its own. Collective.
template <class Visit>
void run_wave(const TileCut& cut, const std::vector<int>& tiles, const std::vector<Grid<std::int64_t>>& receivers, Wave wave,
              std::vector<std::vector<double>>& values, TileExchange& exchange, Visit&& visit) {
  std::vector<TileCells> cells;
  cells.reserve(tiles.size());
  for (int t : tiles) cells.emplace_back(cut, t);
  std::vector<std::vector<std::uint8_t>> pending(tiles.size());
  std::vector<std::vector<std::size_t>> ready(tiles.size());
  std::vector<std::size_t> done(tiles.size(), 0);
  const auto receiver_of = [&](std::size_t k, int x, int y) { return receivers[k](x - cells[k].halo().x0, y - cells[k].halo().y0); };
  // The own cells waiting for cell (x, y) of tile k's haloed rectangle, one fewer thing each.
  const auto release = [&](std::size_t k, int x, int y) {
    const TileCells& c = cells[k];
    const auto wake = [&](int wx, int wy) {
      const std::size_t l = c.local(wx, wy);
      if (--pending[k][l] == 0) ready[k].push_back(l);
    };
    if (wave == Wave::outlets_first) {
      c.for_donors(x, y, receivers[k], [&](int dx, int dy) {
        if (c.own().contains(dx, dy)) wake(dx, dy);
      });
    } else {
      const WorldCell r = receiver_of(k, x, y);
      if (r != cut.index(x, y) && c.owns(r)) wake(cut.x_of(r), cut.y_of(r));
    }
  };
  parallel_for(std::size_t{0}, tiles.size(), [&](std::size_t k) {
    const TileCells& c = cells[k];
    pending[k].assign(c.owned_count(), 0);
    for (int y = c.own().y0; y < c.own().y1; ++y)
      for (int x = c.own().x0; x < c.own().x1; ++x) {
        std::uint8_t waits = 0;
        if (wave == Wave::outlets_first)
          waits = receiver_of(k, x, y) != cut.index(x, y) ? 1 : 0;
        else
          c.for_donors(x, y, receivers[k], [&](int, int) { ++waits; });
        pending[k][c.local(x, y)] = waits;
        if (waits == 0) ready[k].push_back(c.local(x, y));
      }
  });
  // Tiles work on their own cells at once (visit may touch only tile k's data); what they send is
  // gathered per tile, then in tile order.
  std::vector<std::vector<std::pair<int, CellNumber>>> sends_of(tiles.size());
  for (;;) {
    parallel_for(std::size_t{0}, tiles.size(), [&](std::size_t k) {
      const TileCells& c = cells[k];
      std::vector<std::pair<int, CellNumber>>& sends = sends_of[k];
      sends.clear();
      while (!ready[k].empty()) {
        const std::size_t l = ready[k].back();
        ready[k].pop_back();
        const int x = c.own().x0 + static_cast<int>(l % c.own().width()), y = c.own().y0 + static_cast<int>(l / c.own().width());
        const double v = visit(k, x, y);
        values[k][c.haloed(x, y)] = v;
        ++done[k];
        release(k, x, y);
        // The cells of other tiles that wait for this one.
        if (wave == Wave::outlets_first) {
          c.for_donors(x, y, receivers[k], [&](int dx, int dy) {
            if (!c.own().contains(dx, dy)) sends.push_back({cut.tile_at(dx, dy), {cut.index(x, y), v}});
          });
        } else {
          const WorldCell r = receiver_of(k, x, y);
          if (r != cut.index(x, y) && !c.owns(r)) sends.push_back({cut.tile_of(r), {cut.index(x, y), v}});
        }
      }
    });
    std::vector<std::pair<int, CellNumber>> sends;  // (tile, cell and value)
    for (const auto& part : sends_of) sends.insert(sends.end(), part.begin(), part.end());
    // One value per (tile, cell): a cell with two donors in one other tile is sent there once.
    std::sort(sends.begin(), sends.end(),
              [](const auto& a, const auto& b) { return a.first != b.first ? a.first < b.first : a.second.cell < b.second.cell; });
    sends.erase(std::unique(sends.begin(), sends.end(),
                            [](const auto& a, const auto& b) { return a.first == b.first && a.second.cell == b.second.cell; }),
                sends.end());
    std::vector<TileMessage> outgoing;
    for (std::size_t s = 0; s < sends.size();) {
      std::vector<CellNumber> batch;
      const int to = sends[s].first;
      for (; s < sends.size() && sends[s].first == to; ++s) batch.push_back(sends[s].second);
      outgoing.push_back({root_tile, to, Packer().put(batch).take()});
    }
    if (exchange.sum(static_cast<std::int64_t>(outgoing.size())) == 0) break;
    const std::vector<TileMessage> incoming = exchange.exchange(std::move(outgoing));
    parallel_for(std::size_t{0}, tiles.size(), [&](std::size_t k) {
      for (const TileMessage* m : addressed_to(incoming, tiles[k]))
        for (const CellNumber& cn : Unpacker(m->bytes).take<CellNumber>()) {
          const int x = cut.x_of(cn.cell), y = cut.y_of(cn.cell);
          values[k][cells[k].haloed(x, y)] = cn.value;
          release(k, x, y);
        }
    });
  }
  for (std::size_t k = 0; k < tiles.size(); ++k)
    if (done[k] != cells[k].owned_count()) throw std::logic_error("a tiled wavefront left cells undone: the receivers hold a cycle");
}

}  // namespace sansui::water::tiled

// Exact flow routing of a tiled world (see tiled_routing.hpp).
#include "water/tiled_routing.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "core/parallel.hpp"
#include "water/flow.hpp"
#include "water/neighbours.hpp"

namespace sansui::water {
namespace {

using WorldCell = std::int64_t;
/// A basin of the world: the outlets' (all cells that drain off the map or into the sea), or a
/// pit's, named by the pit's world index.
using Basin = std::int64_t;
constexpr Basin outlet_basin = -1;
/// Where a cell's flow ends inside its tile: a basin (>= -1), or the cell v of another tile it
/// flows into, written -2 - v.
constexpr std::int64_t leaves_to(WorldCell v) {
  return -2 - v;
}
constexpr bool leaves(std::int64_t end) {
  return end <= -2;
}
constexpr WorldCell left_to(std::int64_t end) {
  return -2 - end;
}

/// The four neighbours ahead in raster order, as depression_routing.cpp pairs cells (its names: one unity batch may hold both files).
constexpr std::array<int, 4> pair_dx = {1, 1, 0, -1};
constexpr std::array<int, 4> pair_dy = {0, 1, 1, 1};

/// A pair of basins that meet on a tile, and the lowest pass between them found there. `a` is the
/// basin of the cell at `position` (world cell * 4 + direction), `b` that of its neighbour ahead.
/// Ordered as the untiled Kruskal orders its keys: by pass height, then position.
struct Link {
  Basin a, b;
  std::uint64_t position;
  float height;
  std::uint32_t padding = 0;
  bool operator<(const Link& other) const {
    const std::uint32_t mine = ordered_bits(height), theirs = ordered_bits(other.height);
    return mine != theirs ? mine < theirs : position < other.position;
  }
};

using BasinPair = std::pair<Basin, Basin>;
struct BasinPairHash {
  std::size_t operator()(const BasinPair& p) const {
    return std::hash<std::uint64_t>()(static_cast<std::uint64_t>(p.first) * 0x9e3779b97f4a7c15ull ^ static_cast<std::uint64_t>(p.second));
  }
};

struct CellValue {
  WorldCell cell;
  std::int64_t value;
};
struct BasinLevel {
  Basin basin;
  float level;
  std::uint32_t padding = 0;
};
/// A carve that goes on at `cell`, whose receiver becomes `previous`.
struct Carve {
  WorldCell cell, previous;
};

/// A tile's working state.
class TileRouting {
 public:
  TileRouting(const TileCut& cut, RoutedTile& out, const Outlets& outlets) : cut_(cut), out_(out), outlets_(outlets) {
    own_ = cut.owned(out.tile), halo_ = cut.haloed(out.tile);
  }

  /// Step 1: D8 receivers, and where each cell's flow ends in the tile; returns the ends of the
  /// cells on the tile's border, for the root.
  std::vector<CellValue> receivers_and_ends() {
    const Grid<CellIndex> d8 = d8_receivers(out_.heights, outlets_);
    out_.receiver.resize(cells());
    for (int y = own_.y0; y < own_.y1; ++y)
      for (int x = own_.x0; x < own_.x1; ++x) {
        const CellIndex r = d8(x - halo_.x0, y - halo_.y0);
        out_.receiver[local(x, y)] = cut_.index(halo_.x0 + r % halo_.width(), halo_.y0 + r / halo_.width());
      }
    donors_first();
    end_.assign(cells(), 0);
    for (std::size_t k = order_.size(); k-- > 0;) {
      const std::size_t c = order_[k];
      const WorldCell self = world(c), r = out_.receiver[c];
      if (r == self)
        end_[c] = is_outlet_at(cut_.x_of(self), cut_.y_of(self)) ? outlet_basin : self;
      else if (!owns(r))
        end_[c] = leaves_to(r);
      else
        end_[c] = end_[local(r)];
    }
    std::vector<CellValue> border;
    for_border([&](int x, int y) { border.push_back({cut_.index(x, y), end_[local(x, y)]}); });
    return border;
  }

  /// Step 2: with the basins of the halo (from the root), the basin of every cell, and the
  /// lowest pass between every two basins that meet here.
  std::vector<Link> basins_and_links(const std::vector<CellValue>& halo_basins) {
    basin_.assign(static_cast<std::size_t>(halo_.width()) * halo_.height(), outlet_basin);
    for (const CellValue& hv : halo_basins) basin_[haloed(cut_.x_of(hv.cell), cut_.y_of(hv.cell))] = hv.value;
    for (int y = own_.y0; y < own_.y1; ++y)
      for (int x = own_.x0; x < own_.x1; ++x) {
        const std::int64_t end = end_[local(x, y)];
        basin_[haloed(x, y)] = leaves(end) ? basin_[haloed(cut_.x_of(left_to(end)), cut_.y_of(left_to(end)))] : end;
      }
    std::unordered_map<BasinPair, std::size_t, BasinPairHash> slot;  // basin pair -> its link
    std::vector<Link> links;
    for (int y = own_.y0; y < own_.y1; ++y)
      for (int x = own_.x0; x < own_.x1; ++x)
        for (std::size_t k = 0; k < 4; ++k) {
          const int nx = x + pair_dx[k], ny = y + pair_dy[k];
          if (nx < 0 || nx >= cut_.width || ny >= cut_.height) continue;
          const Basin a = basin_[haloed(x, y)], b = basin_[haloed(nx, ny)];
          if (a == b) continue;
          const float pass = std::max(height(x, y), height(nx, ny));
          const Link link{a, b, static_cast<std::uint64_t>(cut_.index(x, y)) * 4 + k, pass};
          auto [at, added] = slot.try_emplace(BasinPair{std::min(a, b), std::max(a, b)}, links.size());
          if (added)
            links.push_back(link);
          else if (link < links[at->second])
            links[at->second] = link;
        }
    return links;
  }

  /// The distinct basins of the tile's cells.
  std::vector<Basin> own_basins() const {
    // Neighbouring cells mostly share a basin: a run of one basin is offered once.
    std::unordered_set<Basin> seen;
    Basin last = outlet_basin - 1;
    for (int y = own_.y0; y < own_.y1; ++y)
      for (int x = own_.x0; x < own_.x1; ++x)
        if (const Basin b = basin_[haloed(x, y)]; b != last) seen.insert(b), last = b;
    std::vector<Basin> found(seen.begin(), seen.end());
    std::sort(found.begin(), found.end());
    return found;
  }

  /// Step 3: water levels from the basins' levels.
  void water_levels(const std::vector<BasinLevel>& levels) {
    std::unordered_map<Basin, float> level_of;
    for (const BasinLevel& bl : levels) level_of.emplace(bl.basin, bl.level);
    out_.water_level = Heightfield::uninitialized(own_.width(), own_.height(), out_.heights.cell_size_m);
    for (int y = own_.y0; y < own_.y1; ++y)
      for (int x = own_.x0; x < own_.x1; ++x) {
        const auto it = level_of.find(basin_[haloed(x, y)]);
        const float level = it == level_of.end() ? -std::numeric_limits<float>::infinity() : it->second;
        out_.water_level(x - own_.x0, y - own_.y0) = std::max(height(x, y), level);
      }
  }

  /// Step 4: carves from `starts`; returns the carves that go on in other tiles.
  void carve(const std::vector<Carve>& starts, std::vector<Carve>& onward) {
    for (Carve c : starts) {
      WorldCell previous = c.previous, cell = c.cell;
      for (;;) {
        std::int64_t& rec = out_.receiver[local(cut_.x_of(cell), cut_.y_of(cell))];
        const WorldCell next = rec;
        rec = previous;
        if (next == cell) break;
        if (!owns(next)) {
          onward.push_back({next, cell});
          break;
        }
        previous = cell, cell = next;
      }
    }
  }

  /// Step 5: the tile's own drainage counts; returns the counts that leave the tile (cell,
  /// receiver, count) and, for each border cell, the cell its flow leaves the tile from (-1: it
  /// ends in the tile).
  void count_cells(std::vector<CellValue>& leaving_counts, std::vector<CellValue>& leaving_to, std::vector<CellValue>& border_exits) {
    donors_first();
    counts_.assign(cells(), 1);
    for (std::size_t c : order_) {
      const WorldCell r = out_.receiver[c];
      if (r != world(c) && owns(r)) counts_[local(r)] += counts_[c];
    }
    std::vector<std::int64_t> exit(cells(), -1);
    for (std::size_t k = order_.size(); k-- > 0;) {
      const std::size_t c = order_[k];
      const WorldCell r = out_.receiver[c];
      exit[c] = r == world(c) ? -1 : !owns(r) ? world(c) : exit[local(r)];
      if (r != world(c) && !owns(r)) leaving_counts.push_back({world(c), counts_[c]}), leaving_to.push_back({world(c), r});
    }
    for_border([&](int x, int y) { border_exits.push_back({cut_.index(x, y), exit[local(x, y)]}); });
  }

  /// Step 6: adds what flows in from other tiles along its paths; the areas.
  void add_inflows(const std::vector<CellValue>& inflows, double cell_area) {
    std::vector<std::int64_t> add(cells(), 0);
    for (const CellValue& in : inflows) add[local(cut_.x_of(in.cell), cut_.y_of(in.cell))] += in.value;
    for (std::size_t c : order_) {
      counts_[c] += add[c];
      const WorldCell r = out_.receiver[c];
      if (r != world(c) && owns(r)) add[local(r)] += add[c];
    }
    out_.area_m2 = Grid<double>::uninitialized(own_.width(), own_.height(), out_.heights.cell_size_m);
    double* area = out_.area_m2.data();
    for (std::size_t c = 0; c < cells(); ++c) area[c] = static_cast<double>(counts_[c]) * cell_area;
  }

 private:
  std::size_t cells() const { return static_cast<std::size_t>(own_.width()) * own_.height(); }
  std::size_t local(int x, int y) const { return static_cast<std::size_t>(y - own_.y0) * own_.width() + (x - own_.x0); }
  std::size_t local(WorldCell i) const { return local(cut_.x_of(i), cut_.y_of(i)); }
  std::size_t haloed(int x, int y) const { return static_cast<std::size_t>(y - halo_.y0) * halo_.width() + (x - halo_.x0); }
  WorldCell world(std::size_t c) const {
    return cut_.index(own_.x0 + static_cast<int>(c % own_.width()), own_.y0 + static_cast<int>(c / own_.width()));
  }
  bool owns(WorldCell i) const { return own_.contains(cut_.x_of(i), cut_.y_of(i)); }
  float height(int x, int y) const { return out_.heights(x - halo_.x0, y - halo_.y0); }
  bool is_outlet_at(int x, int y) const {
    if (x == 0 || y == 0 || x == cut_.width - 1 || y == cut_.height - 1) return true;
    return outlets_.sea_level_m && static_cast<double>(height(x, y)) <= *outlets_.sea_level_m;
  }
  template <class F>
  void for_border(F&& f) const {
    for (int y = own_.y0; y < own_.y1; ++y)
      for (int x = own_.x0; x < own_.x1; ++x)
        if (y == own_.y0 || y == own_.y1 - 1 || x == own_.x0 || x == own_.x1 - 1) f(x, y);
  }
  /// order_: the tile's cells, every donor before its receiver (receivers in other tiles ignored).
  void donors_first() {
    std::vector<std::uint8_t> pending(cells(), 0);
    for (std::size_t c = 0; c < cells(); ++c) {
      const WorldCell r = out_.receiver[c];
      if (r != world(c) && owns(r)) ++pending[local(r)];
    }
    order_.clear();
    order_.reserve(cells());
    for (std::size_t c = 0; c < cells(); ++c)
      if (pending[c] == 0) order_.push_back(static_cast<std::uint32_t>(c));
    for (std::size_t head = 0; head < order_.size(); ++head) {
      const std::size_t c = order_[head];
      const WorldCell r = out_.receiver[c];
      if (r != world(c) && owns(r) && --pending[local(r)] == 0) order_.push_back(static_cast<std::uint32_t>(local(r)));
    }
  }

  const TileCut& cut_;
  RoutedTile& out_;
  Outlets outlets_;
  Rect own_, halo_;
  std::vector<std::uint32_t> order_;  // local indices: a tile has fewer than 2^32 cells
  std::vector<std::int64_t> end_;
  std::vector<Basin> basin_;  // over the haloed rectangle
  std::vector<std::int64_t> counts_;
};

/// The root's step 1: every border cell's world basin, from the tiles' ends.
std::unordered_map<WorldCell, Basin> border_basins(const std::vector<TileMessage>& incoming) {
  std::unordered_map<WorldCell, std::int64_t> end;
  for (const TileMessage& m : incoming)
    for (const CellValue& cv : Unpacker(m.bytes).take<CellValue>()) end.emplace(cv.cell, cv.value);
  std::unordered_map<WorldCell, Basin> basin;
  std::vector<WorldCell> path;
  for (const auto& [cell, first_end] : end) {
    WorldCell c = cell;
    std::int64_t e = first_end;
    while (leaves(e) && !basin.contains(c)) path.push_back(c), c = left_to(e), e = end.at(c);
    const Basin b = basin.contains(c) ? basin.at(c) : e;
    for (WorldCell p : path) basin[p] = b;
    basin[c] = b;
    path.clear();
  }
  return basin;
}

/// The root's step 3: the spanning tree of the basin graph walked from the outlets: each
/// basin's level and the carve over its pass (inside cell, outside cell).
struct TreeAnswer {
  std::unordered_map<Basin, float> level;
  std::vector<Carve> carves;
  std::int64_t depressions = 0;
};
TreeAnswer spanning_tree(const TileCut& cut, std::vector<Link> links, std::vector<Basin> basins) {
  std::sort(links.begin(), links.end());
  basins.push_back(outlet_basin);
  std::sort(basins.begin(), basins.end());
  basins.erase(std::unique(basins.begin(), basins.end()), basins.end());
  const auto id = [&](Basin b) { return static_cast<std::size_t>(std::lower_bound(basins.begin(), basins.end(), b) - basins.begin()); };
  std::vector<std::size_t> parent(basins.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const auto find = [&](std::size_t b) {
    while (parent[b] != b) parent[b] = parent[parent[b]], b = parent[b];
    return b;
  };
  std::vector<Link> tree;
  for (const Link& l : links) {
    if (tree.size() + 1 >= basins.size()) break;
    const std::size_t ra = find(id(l.a)), rb = find(id(l.b));
    if (ra == rb) continue;
    parent[std::max(ra, rb)] = std::min(ra, rb);
    tree.push_back(l);
  }
  std::vector<std::vector<std::size_t>> edges(basins.size());
  for (std::size_t e = 0; e < tree.size(); ++e) edges[id(tree[e].a)].push_back(e), edges[id(tree[e].b)].push_back(e);
  TreeAnswer answer;
  answer.depressions = static_cast<std::int64_t>(basins.size()) - 1;
  std::vector<float> level(basins.size(), -std::numeric_limits<float>::infinity());
  std::vector<char> reached(basins.size(), 0);
  std::vector<std::size_t> queue{id(outlet_basin)};
  reached[queue[0]] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t from = queue[head];
    for (std::size_t e : edges[from]) {
      const Link& l = tree[e];
      const bool a_inside = id(l.a) != from;
      const std::size_t to = id(a_inside ? l.a : l.b);
      if (reached[to]) continue;
      reached[to] = 1;
      level[to] = std::max(l.height, level[from]);
      queue.push_back(to);
      const auto i = static_cast<WorldCell>(l.position / 4);
      const std::size_t k = l.position % 4;
      const WorldCell j = cut.index(cut.x_of(i) + pair_dx[k], cut.y_of(i) + pair_dy[k]);
      answer.carves.push_back(a_inside ? Carve{i, j} : Carve{j, i});
    }
  }
  for (std::size_t b = 0; b < basins.size(); ++b) answer.level.emplace(basins[b], level[b]);
  return answer;
}

/// The root's step 5: what flows into each cell from other tiles, from the counts that leave
/// each tile and where each border cell's flow leaves its tile. Exits form a forest (flow only
/// goes down it), walked upstream first.
std::unordered_map<WorldCell, std::int64_t> inflows(const std::vector<CellValue>& leaving_counts, const std::vector<CellValue>& leaving_to,
                                                    const std::unordered_map<WorldCell, std::int64_t>& border_exit) {
  std::unordered_map<WorldCell, std::int64_t> out, pending, into;
  std::unordered_map<WorldCell, WorldCell> next_exit;
  for (const CellValue& c : leaving_counts) out[c.cell] = c.value, pending.try_emplace(c.cell, 0);
  for (const CellValue& t : leaving_to) {
    const WorldCell e = border_exit.at(t.value);
    next_exit[t.cell] = e;
    if (e >= 0) ++pending[e];
  }
  std::vector<WorldCell> ready;
  for (const auto& [cell, count] : pending)
    if (count == 0) ready.push_back(cell);
  std::unordered_map<WorldCell, WorldCell> target;
  for (const CellValue& t : leaving_to) target[t.cell] = t.value;
  while (!ready.empty()) {
    const WorldCell r = ready.back();
    ready.pop_back();
    into[target.at(r)] += out.at(r);
    const WorldCell e = next_exit.at(r);
    if (e < 0) continue;
    out[e] += out.at(r);
    if (--pending[e] == 0) ready.push_back(e);
  }
  return into;
}

/// The tiles' messages to the root, their values joined.
template <class T>
std::vector<T> joined(const std::vector<TileMessage>& incoming, int part) {
  std::vector<T> all;
  for (const TileMessage* m : addressed_to(incoming, root_tile)) {
    Unpacker in(m->bytes);
    std::vector<T> values;
    for (int k = 0; k <= part; ++k) values = in.template take<T>();
    all.insert(all.end(), values.begin(), values.end());
  }
  return all;
}

/// The part of message `m` addressed to `tile` (one per tile at most).
Unpacker message_for(const std::vector<TileMessage>& incoming, int tile) {
  const std::vector<const TileMessage*> found = addressed_to(incoming, tile);
  static const std::vector<std::byte> none = Packer().put(std::vector<char>{}).put(std::vector<char>{}).take();
  return Unpacker(found.empty() ? std::span<const std::byte>(none) : std::span<const std::byte>(found.front()->bytes));
}

}  // namespace

void route_tiles(const TileCut& cut, std::vector<RoutedTile>& tiles, const Outlets& outlets, double cell_size_m, TileExchange& exchange) {
  std::vector<TileRouting> work;
  work.reserve(tiles.size());
  for (RoutedTile& t : tiles) work.emplace_back(cut, t, outlets);
  const bool root = exchange.rank() == 0;

  // 1. Ends of the border cells to the root; the basins of each tile's halo back.
  // Each phase works on the tiles at once (each on its own tile's data), its messages in tile order.
  std::vector<TileMessage> outgoing(tiles.size());
  parallel_for(std::size_t{0}, tiles.size(), [&](std::size_t k) {
    outgoing[k] = {tiles[k].tile, root_tile, Packer().put(work[k].receivers_and_ends()).take()};
  });
  std::vector<TileMessage> incoming = exchange.exchange(std::move(outgoing));
  outgoing.clear();
  if (root) {
    const std::unordered_map<WorldCell, Basin> basin = border_basins(incoming);
    for (int t = 0; t < cut.tiles(); ++t) {
      const Rect own = cut.owned(t), halo = cut.haloed(t);
      std::vector<CellValue> ring;
      for (int y = halo.y0; y < halo.y1; ++y)
        for (int x = halo.x0; x < halo.x1; ++x)
          if (!own.contains(x, y)) ring.push_back({cut.index(x, y), basin.at(cut.index(x, y))});
      outgoing.push_back({root_tile, t, Packer().put(ring).take()});
    }
  }
  incoming = exchange.exchange(std::move(outgoing));
  outgoing.clear();

  // 2. Links and basins to the root; levels and carves back.
  outgoing.resize(tiles.size());
  parallel_for(std::size_t{0}, tiles.size(), [&](std::size_t k) {
    const std::vector<Link> links = work[k].basins_and_links(message_for(incoming, tiles[k].tile).take<CellValue>());
    outgoing[k] = {tiles[k].tile, root_tile, Packer().put(links).put(work[k].own_basins()).take()};
  });
  incoming = exchange.exchange(std::move(outgoing));
  outgoing.clear();
  if (root) {
    // Every tile's message: its links, then its basins.
    std::vector<Link> links;
    std::vector<Basin> basins;
    std::vector<std::vector<Basin>> basins_of(static_cast<std::size_t>(cut.tiles()));
    for (const TileMessage* m : addressed_to(incoming, root_tile)) {
      Unpacker in(m->bytes);
      const std::vector<Link> l = in.take<Link>();
      links.insert(links.end(), l.begin(), l.end());
      basins_of[static_cast<std::size_t>(m->from)] = in.take<Basin>();
      basins.insert(basins.end(), basins_of[static_cast<std::size_t>(m->from)].begin(), basins_of[static_cast<std::size_t>(m->from)].end());
    }
    const TreeAnswer tree = spanning_tree(cut, std::move(links), std::move(basins));
    std::vector<std::vector<Carve>> carves(static_cast<std::size_t>(cut.tiles()));
    for (const Carve& c : tree.carves) carves[static_cast<std::size_t>(cut.tile_of(c.cell))].push_back(c);
    for (int t = 0; t < cut.tiles(); ++t) {
      std::vector<BasinLevel> levels;
      for (Basin b : basins_of[static_cast<std::size_t>(t)]) levels.push_back({b, tree.level.at(b)});
      outgoing.push_back(
          {root_tile, t,
           Packer().put(levels).put(carves[static_cast<std::size_t>(t)]).put(std::vector<std::int64_t>{tree.depressions}).take()});
    }
  }
  incoming = exchange.exchange(std::move(outgoing));
  outgoing.clear();

  // 3-4. Water levels, then the carves, in rounds while any goes on into another tile.
  std::vector<std::vector<Carve>> onward_of(tiles.size());
  parallel_for(std::size_t{0}, tiles.size(), [&](std::size_t k) {
    Unpacker in = message_for(incoming, tiles[k].tile);
    work[k].water_levels(in.take<BasinLevel>());
    work[k].carve(in.take<Carve>(), onward_of[k]);
    const std::vector<std::int64_t> depressions = in.take<std::int64_t>();
    tiles[k].depressions = depressions.empty() ? 0 : depressions.front();
  });
  std::vector<Carve> onward;
  for (const auto& part : onward_of) onward.insert(onward.end(), part.begin(), part.end());
  for (;;) {
    std::vector<std::vector<Carve>> by_tile(static_cast<std::size_t>(cut.tiles()));
    for (const Carve& c : onward) by_tile[static_cast<std::size_t>(cut.tile_of(c.cell))].push_back(c);
    onward.clear();
    std::int64_t sent = 0;
    for (int t = 0; t < cut.tiles(); ++t)
      if (!by_tile[static_cast<std::size_t>(t)].empty())
        outgoing.push_back({root_tile, t, Packer().put(by_tile[static_cast<std::size_t>(t)]).take()}), ++sent;
    if (exchange.sum(sent) == 0) break;
    incoming = exchange.exchange(std::move(outgoing));
    outgoing.clear();
    for (std::size_t k = 0; k < tiles.size(); ++k)
      for (const TileMessage* m : addressed_to(incoming, tiles[k].tile)) work[k].carve(Unpacker(m->bytes).take<Carve>(), onward);
  }

  // 5. Cell counts: what leaves each tile to the root, what enters each tile back.
  outgoing.resize(tiles.size());
  parallel_for(std::size_t{0}, tiles.size(), [&](std::size_t k) {
    std::vector<CellValue> leaving_counts, leaving_to, border_exits;
    work[k].count_cells(leaving_counts, leaving_to, border_exits);
    outgoing[k] = {tiles[k].tile, root_tile, Packer().put(leaving_counts).put(leaving_to).put(border_exits).take()};
  });
  incoming = exchange.exchange(std::move(outgoing));
  outgoing.clear();
  if (root) {
    const std::vector<CellValue> leaving_counts = joined<CellValue>(incoming, 0), leaving_to = joined<CellValue>(incoming, 1);
    std::unordered_map<WorldCell, std::int64_t> border_exit;
    for (const CellValue& cv : joined<CellValue>(incoming, 2)) border_exit.emplace(cv.cell, cv.value);
    std::vector<std::vector<CellValue>> into(static_cast<std::size_t>(cut.tiles()));
    for (const auto& [cell, count] : inflows(leaving_counts, leaving_to, border_exit))
      into[static_cast<std::size_t>(cut.tile_of(cell))].push_back({cell, count});
    for (int t = 0; t < cut.tiles(); ++t) outgoing.push_back({root_tile, t, Packer().put(into[static_cast<std::size_t>(t)]).take()});
  }
  incoming = exchange.exchange(std::move(outgoing));
  const double cell_area = cell_size_m * cell_size_m;
  parallel_for(std::size_t{0}, tiles.size(),
               [&](std::size_t k) { work[k].add_inflows(message_for(incoming, tiles[k].tile).take<CellValue>(), cell_area); });
}

}  // namespace sansui::water

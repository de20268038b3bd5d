// Rivers and lakes of a tiled world, joined at the root (see tiled_water.hpp).
#include "scene/tiled_water.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "scene/water_geojson.hpp"
#include "water/neighbours.hpp"
#include "water/rivers.hpp"
#include "water/surface_water.hpp"
#include "water/tiled_wave.hpp"

namespace sansui::scene {
namespace {

using water::tiled::TileCells;
using water::tiled::WorldCell;

constexpr WorldCell no_cell = -1;
constexpr double no_area = std::numeric_limits<double>::quiet_NaN();

// ---------------------------------------------------------------------------------------------
// Rivers: each tile's pieces of reaches.

/// Strahler orders over each tile's haloed rectangle (its own cells, and the cells of other tiles
/// that drain into them), 0 off the channels. rivers.cpp pushes each order to the receiver; here
/// each cell pulls from its donors the same rule: the highest order among its channel donors,
/// plus one where two or more share it (1 at a source). Collective.
std::vector<std::vector<double>> strahler_orders(const TileCut& cut, const std::vector<const water::RoutedTile*>& tiles,
                                                 const std::vector<Grid<std::int64_t>>& receivers, double channel_area_m2,
                                                 TileExchange& exchange) {
  std::vector<int> ids;
  std::vector<TileCells> cells;
  std::vector<std::vector<double>> orders;
  for (const water::RoutedTile* t : tiles) {
    ids.push_back(t->tile);
    cells.emplace_back(cut, t->tile);
    orders.emplace_back(cells.back().haloed_count(), 0.0);
  }
  const auto visit = [&](std::size_t k, int x, int y) {
    const TileCells& c = cells[k];
    if (tiles[k]->area_m2(x - c.own().x0, y - c.own().y0) < channel_area_m2) return 0.0;
    double highest = 0.0;
    int sharing = 0;
    c.for_donors(x, y, receivers[k], [&](int dx, int dy) {
      const double order = orders[k][c.haloed(dx, dy)];
      if (order > highest)
        highest = order, sharing = 1;
      else if (order > 0.0 && order == highest)
        ++sharing;
    });
    return highest == 0.0 ? 1.0 : highest + (sharing >= 2 ? 1.0 : 0.0);
  };
  water::tiled::run_wave(cut, ids, receivers, water::tiled::Wave::sources_first, orders, exchange, visit);
  return orders;
}

/// A piece of a reach inside one tile. Its cells follow the pieces before it in Pieces::cells.
struct PieceHead {
  WorldCell continues_to = no_cell;  ///< the cell of another tile the reach goes on into, or none
  double last_area_m2 = 0.0;         ///< drainage area at the piece's last cell
  double before_last_area_m2 = 0.0;  ///< and at the cell before it (no_area in a piece of one cell)
  std::int64_t cells = 0;
  std::int32_t strahler_order = 0;
  std::int32_t starts_reach = 0;  ///< 1: from a source or a confluence; 0: where a reach enters the tile
};

struct Pieces {
  std::vector<PieceHead> heads;
  std::vector<WorldCell> cells;
};

/// A tile's channels after the Strahler wave: where reaches start, and the pieces they make.
class TileRivers {
 public:
  TileRivers(const TileCut& cut, const water::RoutedTile& tile, const Grid<std::int64_t>& receivers, const std::vector<double>& orders)
      : cells_(cut, tile.tile), tile_(tile), orders_(orders) {
    const Rect& own = cells_.own();
    channel_donors_.assign(cells_.owned_count(), 0);
    enters_.assign(cells_.owned_count(), 0);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x)
        cells_.for_donors(x, y, receivers, [&](int dx, int dy) {
          if (orders_[cells_.haloed(dx, dy)] == 0.0) return;
          ++channel_donors_[cells_.local(x, y)];
          if (!own.contains(dx, dy)) enters_[cells_.local(x, y)] = 1;
        });
  }

  /// The pieces in raster order of their first cells: from each reach's start (a channel cell
  /// with no channel donor or with two or more), and from each cell where a reach enters from
  /// another tile, down to a confluence, an outlet or the tile's edge.
  Pieces pieces() const {
    Pieces out;
    const Rect& own = cells_.own();
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) {
        const std::size_t c = cells_.local(x, y);
        if (order(x, y) == 0.0) continue;
        if (channel_donors_[c] != 1)
          trace(x, y, true, out);
        else if (enters_[c])
          trace(x, y, false, out);
      }
    return out;
  }

 private:
  double order(int x, int y) const { return orders_[cells_.haloed(x, y)]; }
  double area(WorldCell i) const {
    const TileCut& cut = cells_.cut();
    return tile_.area_m2(cut.x_of(i) - cells_.own().x0, cut.y_of(i) - cells_.own().y0);
  }
  WorldCell receiver(WorldCell i) const { return tile_.receiver[cells_.local(cells_.cut().x_of(i), cells_.cut().y_of(i))]; }
  std::uint8_t channel_donors(WorldCell i) const { return channel_donors_[cells_.local(cells_.cut().x_of(i), cells_.cut().y_of(i))]; }

  /// Follows the reach from (x, y) down while it stays in the tile, as extract_rivers does.
  void trace(int x, int y, bool starts_reach, Pieces& out) const {
    WorldCell at = cells_.cut().index(x, y);
    PieceHead head{no_cell, area(at), no_area, 1, static_cast<std::int32_t>(order(x, y)), starts_reach ? 1 : 0};
    out.cells.push_back(at);
    for (;;) {
      const WorldCell next = receiver(at);
      if (next == at) break;
      if (!cells_.owns(next)) {
        head.continues_to = next;
        break;
      }
      out.cells.push_back(next);
      head.before_last_area_m2 = head.last_area_m2, head.last_area_m2 = area(next), ++head.cells;
      at = next;
      if (channel_donors(next) != 1) break;  // a confluence: the next reach starts here
    }
    out.heads.push_back(head);
  }

  TileCells cells_;
  const water::RoutedTile& tile_;
  const std::vector<double>& orders_;         // over the haloed rectangle
  std::vector<std::uint8_t> channel_donors_;  // per own cell
  std::vector<std::uint8_t> enters_;          // per own cell: a channel donor lies in another tile
};

// ---------------------------------------------------------------------------------------------
// Lakes: each tile's flooded cells.

/// Flooded cells along a row: `length` cells from world cell `first`.
struct Run {
  WorldCell first = 0;
  std::int64_t length = 0;
};
struct FloodedCell {
  float level_m = 0.0f, ground_m = 0.0f;
};
struct Flooded {
  std::vector<Run> runs;
  std::vector<FloodedCell> cells;  ///< the runs' cells in order
};

/// The tile's cells whose water level stands above the ground, as lakes_of finds them.
Flooded flooded_cells(const TileCut& cut, const water::RoutedTile& tile) {
  const Rect own = cut.owned(tile.tile), halo = cut.haloed(tile.tile);
  Flooded out;
  for (int y = own.y0; y < own.y1; ++y)
    for (int x = own.x0; x < own.x1; ++x) {
      const float level = tile.water_level(x - own.x0, y - own.y0), ground = tile.heights(x - halo.x0, y - halo.y0);
      if (!(level > ground)) continue;
      if (out.runs.empty() || out.runs.back().first + out.runs.back().length != cut.index(x, y) || x == own.x0)
        out.runs.push_back({cut.index(x, y), 0});
      ++out.runs.back().length;
      out.cells.push_back({level, ground});
    }
  return out;
}

// ---------------------------------------------------------------------------------------------
// The root: whole reaches and whole lakes.

struct RootRivers {
  std::vector<PieceHead> heads;
  std::vector<std::size_t> offset;  ///< of each piece's first cell in `cells`
  std::vector<WorldCell> cells;
};
/// The world's flooded cells in raster order, found by their rows.
class RootLakes {
 public:
  std::vector<std::pair<WorldCell, FloodedCell>> cells;
  std::vector<std::size_t> row_begin;  ///< cells of row y: [row_begin[y], row_begin[y + 1])

  /// Sorts the cells and indexes their rows.
  void index_rows(const TileCut& cut) {
    std::sort(cells.begin(), cells.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    row_begin.assign(static_cast<std::size_t>(cut.height) + 1, 0);
    for (const auto& c : cells) ++row_begin[static_cast<std::size_t>(cut.y_of(c.first)) + 1];
    for (std::size_t y = 1; y < row_begin.size(); ++y) row_begin[y] += row_begin[y - 1];
  }
  /// The positions in `cells` of the flooded neighbours of cells[p] (cells.size() for a dry
  /// one), in neighbours.hpp's order. One search per row above and below.
  std::array<std::size_t, 8> neighbours(const TileCut& cut, std::size_t p) const {
    std::array<std::size_t, 8> found;
    found.fill(cells.size());
    const WorldCell i = cells[p].first;
    const int x = cut.x_of(i), y = cut.y_of(i);
    if (x + 1 < cut.width && p + 1 < cells.size() && cells[p + 1].first == i + 1) found[0] = p + 1;
    if (x > 0 && p > 0 && cells[p - 1].first == i - 1) found[4] = p - 1;
    for (const int dy : {-1, 1}) {
      const int ny = y + dy;
      if (ny < 0 || ny >= cut.height) continue;
      const auto last = cells.begin() + static_cast<std::ptrdiff_t>(row_begin[static_cast<std::size_t>(ny) + 1]);
      const WorldCell from = cut.index(std::max(x - 1, 0), ny), to = cut.index(std::min(x + 1, cut.width - 1), ny);
      auto it = std::lower_bound(cells.begin() + static_cast<std::ptrdiff_t>(row_begin[static_cast<std::size_t>(ny)]), last, from,
                                 [](const auto& c, WorldCell v) { return c.first < v; });
      for (; it != last && it->first <= to; ++it)
        found[neighbour_slot(static_cast<int>(it->first - cut.index(x, ny)), dy)] = static_cast<std::size_t>(it - cells.begin());
    }
    return found;
  }

 private:
  /// The place of neighbour (dx, dy) in neighbours.hpp's order.
  static std::size_t neighbour_slot(int dx, int dy) {
    for (std::size_t k = 0; k < 8; ++k)
      if (water::neighbour_dx[k] == dx && water::neighbour_dy[k] == dy) return k;
    return 8;
  }
};

/// The tiles' messages to the root, read into the rivers' pieces and the flooded cells.
void read_tiles(const TileCut& cut, const std::vector<TileMessage>& incoming, RootRivers& rivers, RootLakes& lakes) {
  for (const TileMessage* m : addressed_to(incoming, root_tile)) {
    Unpacker in(m->bytes);
    const std::vector<PieceHead> heads = in.take<PieceHead>();
    const std::vector<WorldCell> cells = in.take<WorldCell>();
    std::size_t at = rivers.cells.size();
    for (const PieceHead& head : heads)
      rivers.heads.push_back(head), rivers.offset.push_back(at), at += static_cast<std::size_t>(head.cells);
    rivers.cells.insert(rivers.cells.end(), cells.begin(), cells.end());
    const std::vector<Run> runs = in.take<Run>();
    const std::vector<FloodedCell> flooded = in.take<FloodedCell>();
    std::size_t f = 0;
    for (const Run& run : runs)
      for (std::int64_t i = 0; i < run.length; ++i) lakes.cells.emplace_back(run.first + i, flooded.at(f++));
  }
  lakes.index_rows(cut);
}

/// One whole reach as it is joined from its pieces; its drainage area is that of the cell
/// before its last (above the confluence), or of its only cell.
struct Reach {
  std::vector<WorldCell> cells;
  double last_area_m2 = no_area, before_last_area_m2 = no_area;

  void append(const RootRivers& rivers, std::size_t piece) {
    const PieceHead& head = rivers.heads[piece];
    const auto first = rivers.cells.begin() + static_cast<std::ptrdiff_t>(rivers.offset[piece]);
    cells.insert(cells.end(), first, first + head.cells);
    before_last_area_m2 = head.cells >= 2 ? head.before_last_area_m2 : last_area_m2;
    last_area_m2 = head.last_area_m2;
  }
  /// Ends the reach at a confluence in another tile (which starts a reach of its own).
  void end_at(WorldCell confluence) {
    cells.push_back(confluence);
    before_last_area_m2 = last_area_m2, last_area_m2 = no_area;
  }
  double area_m2() const { return cells.size() == 1 ? last_area_m2 : before_last_area_m2; }
};

/// The reaches joined from the tiles' pieces, in raster order of their first cells, written as
/// rivers_to_geojson writes them.
std::string joined_rivers(const TileCut& cut, const RootRivers& rivers, const water::FlowParams& params, const contour::GridFrame& world) {
  std::unordered_map<WorldCell, std::size_t> entering;  // pieces that go on with a reach, by first cell
  std::vector<std::size_t> starts;
  for (std::size_t p = 0; p < rivers.heads.size(); ++p)
    if (rivers.heads[p].starts_reach)
      starts.push_back(p);
    else
      entering.emplace(rivers.cells[rivers.offset[p]], p);
  const auto first_cell = [&](std::size_t p) { return rivers.cells[rivers.offset[p]]; };
  std::sort(starts.begin(), starts.end(), [&](std::size_t a, std::size_t b) { return first_cell(a) < first_cell(b); });
  std::vector<io::LineFeature> features;
  int id = 0;
  for (const std::size_t start : starts) {
    Reach reach;
    reach.append(rivers, start);
    for (std::size_t p = start; rivers.heads[p].continues_to != no_cell;) {
      const auto next = entering.find(rivers.heads[p].continues_to);
      if (next == entering.end()) {
        reach.end_at(rivers.heads[p].continues_to);
        break;
      }
      p = next->second;
      reach.append(rivers, p);
    }
    if (reach.cells.size() < 2) continue;  // a line needs two positions
    const double area = reach.area_m2();
    const ReachProperties properties{id++, rivers.heads[start].strahler_order, area, water::river_discharge_m3_per_s(area, params)};
    features.push_back(river_feature(reach.cells, cut.width, world, properties));
  }
  return io::lines_to_geojson(features, "rivers");
}

/// The lakes of the flooded cells (8-connected, as lakes_of labels them, breadth first from the
/// first cell of each in raster order, so that their volumes are summed in the same order),
/// those of min_lake_cells or more written as lakes_to_geojson writes them.
std::string joined_lakes(const TileCut& cut, const RootLakes& lakes, const contour::GridFrame& world) {
  const auto& cells = lakes.cells;
  const double cell_area = world.cell_m * world.cell_m;
  std::vector<std::uint8_t> labelled(cells.size(), 0);
  std::vector<std::size_t> queue;
  std::vector<io::PolygonFeature> features;
  int kept = 0;
  for (std::size_t start = 0; start < cells.size(); ++start) {
    if (labelled[start]) continue;
    LakeProperties lake{kept, cells[start].second.level_m, 0, 0.0};
    Rect box;
    queue.assign(1, start);
    labelled[start] = 1;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const auto& [cell, value] = cells[queue[head]];
      ++lake.cells;
      lake.volume_m3 += (static_cast<double>(value.level_m) - value.ground_m) * cell_area;
      const int x = cut.x_of(cell), y = cut.y_of(cell);
      add_to_box(box, x, y);
      for (const std::size_t n : lakes.neighbours(cut, queue[head])) {
        if (n == cells.size() || labelled[n]) continue;
        labelled[n] = 1;
        queue.push_back(n);
      }
    }
    if (lake.cells < water::min_lake_cells) continue;  // a puddle, as drop_small_lakes drops it
    LakeShore shore(box, world);
    for (const std::size_t q : queue) shore.add(cut.x_of(cells[q].first), cut.y_of(cells[q].first));
    features.push_back(shore.feature(lake));
    ++kept;
  }
  return io::polygons_to_geojson(features, "lakes");
}

}  // namespace

TiledWaterTexts tiled_water_geojson(const TileCut& cut, const std::vector<const water::RoutedTile*>& tiles, const water::FlowParams& params,
                                    const contour::GridFrame& world, TileExchange& exchange) {
  params.validate();
  // 1. Strahler orders, a wavefront down the rivers across tiles.
  const std::vector<Grid<std::int64_t>> receivers = water::tiled::haloed_receivers(cut, tiles, exchange);
  const std::vector<std::vector<double>> orders = strahler_orders(cut, tiles, receivers, params.channel_area_m2, exchange);

  // 2. Each tile's pieces of reaches and flooded cells to the root.
  std::vector<TileMessage> outgoing;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Pieces pieces = TileRivers(cut, *tiles[k], receivers[k], orders[k]).pieces();
    const Flooded flooded = flooded_cells(cut, *tiles[k]);
    outgoing.push_back(
        {tiles[k]->tile, root_tile, Packer().put(pieces.heads).put(pieces.cells).put(flooded.runs).put(flooded.cells).take()});
  }
  const std::vector<TileMessage> incoming = exchange.exchange(std::move(outgoing));
  if (exchange.rank() != 0) return {};

  // 3. The root joins whole reaches and whole lakes.
  RootRivers rivers;
  RootLakes lakes;
  read_tiles(cut, incoming, rivers, lakes);
  return {joined_rivers(cut, rivers, params, world), joined_lakes(cut, lakes, world)};
}

}  // namespace sansui::scene

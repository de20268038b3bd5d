// Erosion of a tiled world (see tiled_erosion.hpp).
#include "water/tiled_erosion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.hpp"
#include "core/exact_sum.hpp"
#include "core/tile_halo.hpp"
#include "water/edge_margin.hpp"
#include "water/erode_cells.hpp"
#include "water/erosion_chain.hpp"
#include "water/flow.hpp"
#include "water/stream_power_cell.hpp"
#include "water/tiled_wave.hpp"

namespace sansui::water {
namespace {

using namespace tiled;

std::vector<const RoutedTile*> routed_of(const std::vector<ErodingTile>& tiles) {
  std::vector<const RoutedTile*> routed;
  routed.reserve(tiles.size());
  for (const ErodingTile& t : tiles) routed.push_back(&t.flow);
  return routed;
}
std::vector<int> ids_of(const std::vector<ErodingTile>& tiles) {
  std::vector<int> ids;
  ids.reserve(tiles.size());
  for (const ErodingTile& t : tiles) ids.push_back(t.tile);
  return ids;
}

/// The tiles' flow routed again over their present heights (the halo exchanged first, the
/// routing moved out and back, not copied). Collective.
void route_in_place(const TileCut& cut, std::vector<ErodingTile>& tiles, std::optional<double> sea_level_m, double cell_size,
                    TileExchange& exchange) {
  exchange_heights_halo(cut, tiles, exchange);
  std::vector<RoutedTile> routed;
  routed.reserve(tiles.size());
  for (ErodingTile& t : tiles) routed.push_back(std::move(t.flow));
  route_tiles(cut, routed, Outlets{sea_level_m}, cell_size, exchange);
  for (std::size_t k = 0; k < tiles.size(); ++k) tiles[k].flow = std::move(routed[k]);
}

/// Messages gathered per tile, in tile order.
std::vector<TileMessage> joined_messages(std::vector<std::vector<TileMessage>>& parts) {
  std::vector<TileMessage> all;
  for (auto& part : parts)
    for (TileMessage& m : part) all.push_back(std::move(m));
  return all;
}

/// Thomas sweeps along lines that cross tiles (rows, or columns), with stream_power_cell.hpp's
/// steps, as stream_power.cpp solves its rows and columns: forward along the tiles of a line
/// carrying (cp, dp) of the last cell, back carrying the solved value of the first. z, fixed:
/// each tile's own cells, row-major.
struct LineTile {
  std::vector<double>* z;
  const std::vector<std::uint8_t>* fixed;
  std::vector<ThomasStep> steps;
};

void sweep_lines(const TileCut& cut, const std::vector<ErodingTile>& tiles, std::vector<LineTile>& lines, bool rows, double alpha,
                 TileExchange& exchange) {
  const int along_tiles = rows ? cut.tiles_x() : cut.tiles_y();
  const int length = rows ? cut.width : cut.height;
  // A tile's lines (rows: y; columns: x) and its span along them (rows: x; columns: y).
  struct Span {
    int line0, line1, pos0, pos1;
  };
  const auto span_of = [&](int t) {
    const Rect r = cut.owned(t);
    if (rows) return Span{std::max(r.y0, 1), std::min(r.y1, cut.height - 1), r.x0, r.x1};
    return Span{r.x0, r.x1, r.y0, r.y1};
  };
  const auto index = [&](int t, int line, int pos) {
    const Rect r = cut.owned(t);
    const int x = rows ? pos : line, y = rows ? line : pos;
    return static_cast<std::size_t>(y - r.y0) * r.width() + (x - r.x0);
  };
  const auto position_in_line = [&](int t) { return rows ? t % cut.tiles_x() : t / cut.tiles_x(); };
  const auto next_tile = [&](int t, int step) { return rows ? t + step : t + step * cut.tiles_x(); };
  for (LineTile& lt : lines) lt.steps.assign(lt.z->size(), {});

  std::vector<TileMessage> incoming;
  // One step of a sweep: the tiles at `step` along their lines at once, each with the numbers its
  // neighbour carried to it; sweep(k, span, carried, to_next) returns what it carries on.
  const auto sweep_step = [&](int step, int direction, auto&& sweep) {
    std::vector<std::vector<TileMessage>> outgoing_of(tiles.size());
    parallel_for(std::size_t{0}, tiles.size(), [&](std::size_t k) {
      const int t = tiles[k].tile;
      if (position_in_line(t) != step) return;
      std::vector<double> carried;
      for (const TileMessage* m : addressed_to(incoming, t)) carried = Unpacker(m->bytes).take<double>();
      bool goes_on = false;
      std::vector<double> onward = sweep(k, span_of(t), carried, goes_on);
      if (goes_on) outgoing_of[k].push_back({t, next_tile(t, direction), Packer().put(onward).take()});
    });
    incoming = exchange.exchange(joined_messages(outgoing_of));
  };
  // Forward sweeps, one tile of each line after the other.
  for (int step = 0; step < along_tiles; ++step)
    sweep_step(step, 1, [&](std::size_t k, const Span& s, const std::vector<double>& carried, bool& goes_on) {
      const int t = tiles[k].tile;
      LineTile& lt = lines[k];
      std::vector<double> last;
      for (int line = s.line0; line < s.line1; ++line) {
        ThomasStep previous;
        int pos = s.pos0;
        if (pos == 0) {  // the line's first cell is fixed
          const std::size_t i = index(t, line, 0);
          previous = lt.steps[i] = thomas_forward(alpha, true, (*lt.z)[i], {});
          pos = 1;
        } else {
          const auto n = static_cast<std::size_t>(line - s.line0);
          previous = {carried.at(2 * n), carried.at(2 * n + 1)};
        }
        for (; pos < s.pos1; ++pos) {
          const std::size_t i = index(t, line, pos);
          previous = lt.steps[i] = thomas_forward(alpha, (*lt.fixed)[i] != 0, (*lt.z)[i], previous);
        }
        last.push_back(previous.cp), last.push_back(previous.dp);
      }
      goes_on = s.pos1 < length;
      return last;
    });
  // Back substitution, the other way.
  incoming.clear();
  for (int step = along_tiles - 1; step >= 0; --step)
    sweep_step(step, -1, [&](std::size_t k, const Span& s, const std::vector<double>& carried, bool& goes_on) {
      const int t = tiles[k].tile;
      LineTile& lt = lines[k];
      std::vector<double> first;
      for (int line = s.line0; line < s.line1; ++line) {
        int pos = s.pos1 - 1;
        double next = 0.0;
        if (s.pos1 == length) {  // the line's last cell is fixed: its value is its dp
          const std::size_t i = index(t, line, pos);
          next = (*lt.z)[i] = lt.steps[i].dp;
          --pos;
        } else {
          next = carried.at(static_cast<std::size_t>(line - s.line0));
        }
        for (; pos >= s.pos0; --pos) {
          const std::size_t i = index(t, line, pos);
          next = (*lt.z)[i] = thomas_back(lt.steps[i], next);
        }
        first.push_back((*lt.z)[index(t, line, s.pos0)]);
      }
      goes_on = s.pos0 > 0;
      return first;
    });
}

ErosionBudget fluvial_passes(const TileCut& cut, std::vector<ErodingTile>& tiles, const StreamPowerParams& params, double cell_size,
                             TileExchange& exchange);

/// stream_power.cpp's diffuse_hillslopes on the tiles' own cells. Collective.
void tiled_diffusion(const TileCut& cut, std::vector<ErodingTile>& tiles, double diffusivity, double years,
                     const std::optional<double>& sea_level_m, double cell_size_m, TileExchange& exchange) {
  if (diffusivity <= 0.0 || years <= 0.0 || cut.width < 3 || cut.height < 3) return;
  const double alpha = diffusivity * years / (cell_size_m * cell_size_m);
  std::vector<std::vector<double>> z(tiles.size());
  std::vector<std::vector<std::uint8_t>> fixed(tiles.size());
  std::vector<LineTile> lines;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Rect own = cut.owned(tiles[k].tile), halo = cut.haloed(tiles[k].tile);
    const Heightfield& h = tiles[k].flow.heights;
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) {
        const float v = h(x - halo.x0, y - halo.y0);
        z[k].push_back(v);
        const bool edge = x == 0 || y == 0 || x == cut.width - 1 || y == cut.height - 1;
        fixed[k].push_back(edge || (sea_level_m && static_cast<double>(v) <= *sea_level_m) ? 1 : 0);
      }
  }
  for (std::size_t k = 0; k < tiles.size(); ++k) lines.push_back({&z[k], &fixed[k], {}});
  sweep_lines(cut, tiles, lines, true, alpha, exchange);
  sweep_lines(cut, tiles, lines, false, alpha, exchange);
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Rect own = cut.owned(tiles[k].tile), halo = cut.haloed(tiles[k].tile);
    std::size_t i = 0;
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) tiles[k].flow.heights(x - halo.x0, y - halo.y0) = static_cast<float>(z[k][i++]);
  }
}

}  // namespace

std::vector<ErodingTile> eroding_tiles(const TileCut& cut, double cell_size_m, TileExchange& exchange,
                                       const std::function<Heightfield(int tile)>& heights_of) {
  std::vector<ErodingTile> tiles;
  for (int t : exchange.my_tiles(cut)) {
    const Rect own = cut.owned(t), halo = cut.haloed(t);
    const Heightfield own_heights = heights_of(t);
    ErodingTile tile;
    tile.tile = t;
    tile.flow.tile = t;
    tile.flow.heights = Heightfield(halo.width(), halo.height(), 0.0f, cell_size_m);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) tile.flow.heights(x - halo.x0, y - halo.y0) = own_heights(x - own.x0, y - own.y0);
    tile.eroded_m = Grid<float>(own.width(), own.height(), 0.0f, cell_size_m);
    tile.deposited_m = Grid<float>(own.width(), own.height(), 0.0f, cell_size_m);
    tiles.push_back(std::move(tile));
  }
  exchange_heights_halo(cut, tiles, exchange);
  return tiles;
}

void exchange_heights_halo(const TileCut& cut, std::vector<ErodingTile>& tiles, TileExchange& exchange) {
  std::vector<int> ids;
  std::vector<Grid<float>*> grids;
  for (ErodingTile& t : tiles) ids.push_back(t.tile), grids.push_back(&t.flow.heights);
  exchange_halo(cut, ids, grids, exchange);
}

ErosionBudget tiled_stream_power_step(const TileCut& cut, std::vector<ErodingTile>& tiles, const StreamPowerParams& params,
                                      TileExchange& exchange) {
  if (!params.diffusivity_m2_per_yr) throw std::logic_error("tiled_stream_power_step needs the diffusivity resolved");
  if (tiles.empty() && exchange.ranks() == 1) return {};
  const double cell_size = tiles.empty() ? 1.0 : tiles.front().flow.heights.cell_size_m;
  route_in_place(cut, tiles, params.sea_level_m, cell_size, exchange);
  const ErosionBudget budget = fluvial_passes(cut, tiles, params, cell_size, exchange);
  tiled_diffusion(cut, tiles, *params.diffusivity_m2_per_yr, params.time_step_yr, params.sea_level_m, cell_size, exchange);
  return budget;
}

namespace {

/// Incision and sediment of a step (its working arrays freed before the diffusion's).
ErosionBudget fluvial_passes(const TileCut& cut, std::vector<ErodingTile>& tiles, const StreamPowerParams& params, double cell_size,
                             TileExchange& exchange) {
  const std::vector<Grid<std::int64_t>> receivers = haloed_receivers(cut, routed_of(tiles), exchange);
  const double dt = params.time_step_yr, cell_area = cell_size * cell_size;
  const double k_dt = params.erodibility * dt;
  const AreaPower area_power(cell_area, params.area_exponent);
  const double straight_power = std::pow(cell_size, params.slope_exponent);
  const double diagonal_power = std::pow(cell_size * neighbour_distance[1], params.slope_exponent);
  const bool linear = params.slope_exponent == 1.0;
  const double uplift = params.uplift_m_per_yr;
  std::vector<TileCells> cells;
  cells.reserve(tiles.size());
  for (const ErodingTile& t : tiles) cells.emplace_back(cut, t.tile);
  const auto receiver_at = [&](std::size_t k, int x, int y) { return receivers[k](x - cells[k].halo().x0, y - cells[k].halo().y0); };
  const auto height_at = [&](std::size_t k, int x, int y) -> float& {
    return tiles[k].flow.heights(x - cells[k].halo().x0, y - cells[k].halo().y0);
  };

  // Incision, outlets first (stream_power.cpp's first pass, cell for cell).
  std::vector<std::vector<double>> incised(tiles.size());
  for (std::size_t k = 0; k < tiles.size(); ++k) incised[k].assign(cells[k].haloed_count(), 0.0);
  run_wave(cut, ids_of(tiles), receivers, Wave::outlets_first, incised, exchange, [&](std::size_t k, int x, int y) {
    const WorldCell i = cut.index(x, y), r = receiver_at(k, x, y);
    const double h = height_at(k, x, y);
    if (r == i) return h;
    const double lifted = h + uplift * dt;
    const double below = incised[k][cells[k].haloed(r)];
    if (lifted <= below) return lifted;
    const bool diagonal = is_diagonal(static_cast<CellIndex>(r - i), cut.width);
    const double f = k_dt * area_power(tiles[k].flow.area_m2(x - cells[k].own().x0, y - cells[k].own().y0)) /
                     (diagonal ? diagonal_power : straight_power);
    if (f == 0.0) return lifted;
    if (linear) return (lifted + f * below) / (1.0 + f);
    return below + solve_incision(lifted - below, f, params.slope_exponent);
  });

  // Sediment, sources first (the second pass): what arrives is the sum of the donors' outflows
  // in raster order, from zero.
  std::vector<ErosionBudget> budgets(tiles.size());  // per tile: the tiles work at once
  std::vector<std::vector<double>> outflow(tiles.size());
  for (std::size_t k = 0; k < tiles.size(); ++k) outflow[k].assign(cells[k].haloed_count(), 0.0);
  run_wave(cut, ids_of(tiles), receivers, Wave::sources_first, outflow, exchange, [&](std::size_t k, int x, int y) {
    const TileCells& c = cells[k];
    double supply = 0.0;
    c.for_donors(x, y, receivers[k], [&](int dx, int dy) { supply += outflow[k][c.haloed(dx, dy)]; });
    const WorldCell i = cut.index(x, y), r = receiver_at(k, x, y);
    ErosionBudget& budget = budgets[k];
    if (r == i) {
      budget.sediment_out_m3 += supply;
      return 0.0;
    }
    float& h = height_at(k, x, y);
    const int lx = x - c.own().x0, ly = y - c.own().y0;
    const double incised_here = incised[k][c.haloed(x, y)];
    const double lifted = static_cast<double>(h) + uplift * dt;
    const float surface = tiles[k].flow.water_level(lx, ly);
    const double area = tiles[k].flow.area_m2(lx, ly);
    double deposit_m3 = 0.0;
    if (surface > h)
      deposit_m3 = std::min(supply, std::max(0.0, (static_cast<double>(surface) - incised_here) * cell_area));
    else
      deposit_m3 = std::min(supply, params.deposition * supply * cell_area / area);
    const auto new_height = static_cast<float>(incised_here + deposit_m3 / cell_area);
    const double removed_m3 = (lifted - static_cast<double>(new_height)) * cell_area;
    if (removed_m3 > 0.0)
      budget.eroded_m3 += removed_m3;
    else
      budget.deposited_m3 -= removed_m3;
    tiles[k].eroded_m(lx, ly) += static_cast<float>(lifted - incised_here);
    tiles[k].deposited_m(lx, ly) += static_cast<float>(deposit_m3 / cell_area);
    h = new_height;
    return supply + removed_m3;
  });
  ErosionBudget budget;
  for (const ErosionBudget& part : budgets) budget += part;
  return budget;
}

}  // namespace

void tiled_follow_inner_land(const TileCut& cut, std::vector<ErodingTile>& tiles, double base_level) {
  const int width = cut.width, height = cut.height;
  if (width < 3 || height < 3) return;
  const auto follow = [base_level](float& edge, float inner) { follow_inner(edge, inner, base_level); };
  for (ErodingTile& t : tiles) {
    const Rect own = cut.owned(t.tile), halo = cut.haloed(t.tile);
    const auto h = [&](int x, int y) -> float& { return t.flow.heights(x - halo.x0, y - halo.y0); };
    // As erode.cpp: the top and bottom rows first, then the left and right columns.
    for (int x = own.x0; x < own.x1; ++x) {
      if (own.y0 == 0) follow(h(x, 0), h(x, 1));
      if (own.y1 == height) follow(h(x, height - 1), h(x, height - 2));
    }
    for (int y = own.y0; y < own.y1; ++y) {
      if (own.x0 == 0) follow(h(0, y), h(1, y));
      if (own.x1 == width) follow(h(width - 1, y), h(width - 2, y));
    }
  }
}

namespace {

/// An exact sum and a count over all tiles: each tile sends its part to the root, which sends
/// the totals back. Collective; a rank without tiles gets zero.
std::pair<ExactSum, std::int64_t> exact_total(const std::vector<ErodingTile>& tiles, const std::vector<ExactSum>& parts,
                                              const std::vector<std::int64_t>& counts, const TileCut& cut, TileExchange& exchange) {
  struct Part {
    long long high;
    unsigned long long low;
    std::int64_t count;
  };
  std::vector<TileMessage> outgoing;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    Part part{0, 0, counts[k]};
    parts[k].to_halves(part.high, part.low);
    outgoing.push_back({tiles[k].tile, root_tile, Packer().put(std::vector<Part>{part}).take()});
  }
  std::vector<TileMessage> incoming = exchange.exchange(std::move(outgoing));
  outgoing.clear();
  if (exchange.rank() == 0) {
    ExactSum total;
    std::int64_t count = 0;
    for (const TileMessage* m : addressed_to(incoming, root_tile))
      for (const Part& part : Unpacker(m->bytes).take<Part>()) total.add(ExactSum::from_halves(part.high, part.low)), count += part.count;
    Part all{0, 0, count};
    total.to_halves(all.high, all.low);
    for (int t = 0; t < cut.tiles(); ++t) outgoing.push_back({root_tile, t, Packer().put(std::vector<Part>{all}).take()});
  }
  incoming = exchange.exchange(std::move(outgoing));
  for (const ErodingTile& t : tiles)
    for (const TileMessage* m : addressed_to(incoming, t.tile)) {
      const Part all = Unpacker(m->bytes).take<Part>().at(0);
      return {ExactSum::from_halves(all.high, all.low), all.count};
    }
  return {ExactSum{}, 0};
}

/// A tile's own cells as a plain grid.
Heightfield own_heights(const TileCut& cut, const ErodingTile& t) {
  const Rect own = cut.owned(t.tile), halo = cut.haloed(t.tile);
  Heightfield h(own.width(), own.height(), 0.0f, t.flow.heights.cell_size_m);
  for (int y = own.y0; y < own.y1; ++y)
    for (int x = own.x0; x < own.x1; ++x) h(x - own.x0, y - own.y0) = t.flow.heights(x - halo.x0, y - halo.y0);
  return h;
}

/// fine_detail (erode.hpp) of the tiles' own cells, from a ring of 2^levels cells. Collective.
std::vector<Grid<float>> tiled_fine_detail(const TileCut& cut, const std::vector<ErodingTile>& tiles, int levels, TileExchange& exchange) {
  const int step = 1 << levels;
  std::vector<Grid<float>> wide(tiles.size());
  std::vector<int> ids;
  std::vector<Grid<float>*> grids;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Rect own = cut.owned(tiles[k].tile), halo = cut.haloed(tiles[k].tile), ring = cut.haloed(tiles[k].tile, step);
    wide[k] = Grid<float>(ring.width(), ring.height(), 0.0f);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) wide[k](x - ring.x0, y - ring.y0) = tiles[k].flow.heights(x - halo.x0, y - halo.y0);
    ids.push_back(tiles[k].tile), grids.push_back(&wide[k]);
  }
  exchange_halo(cut, ids, grids, exchange, step);
  std::vector<Grid<float>> detail;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Rect own = cut.owned(tiles[k].tile), ring = cut.haloed(tiles[k].tile, step);
    Grid<float> d(own.width(), own.height(), 0.0f, tiles[k].flow.heights.cell_size_m);
    if (cut.width > step && cut.height > step) {
      const auto at = [&](int x, int y) { return wide[k](x - ring.x0, y - ring.y0); };
      for (int y = own.y0; y < own.y1; ++y)
        for (int x = own.x0; x < own.x1; ++x) d(x - own.x0, y - own.y0) = fine_detail_at(at, x, y, cut.width, cut.height, levels);
    }
    detail.push_back(std::move(d));
  }
  return detail;
}

/// erode.cpp's keep_detail on the tiles. Collective.
void tiled_keep_detail(const TileCut& cut, std::vector<ErodingTile>& tiles, std::vector<Grid<float>> detail, double weight,
                       double base_level, bool lost_only, TileExchange& exchange) {
  std::vector<ExactSum> squares(tiles.size());
  std::vector<std::int64_t> counts(tiles.size(), 0);
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Rect own = cut.owned(tiles[k].tile), halo = cut.haloed(tiles[k].tile);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x)
        if (static_cast<double>(tiles[k].flow.heights(x - halo.x0, y - halo.y0)) > base_level) {
          const float d = detail[k](x - own.x0, y - own.y0);
          squares[k].add(static_cast<double>(d) * d), ++counts[k];
        }
  }
  const auto [sum, count] = exact_total(tiles, squares, counts, cut, exchange);
  const double size = root_mean_square(sum, count);
  exchange_heights_halo(cut, tiles, exchange);  // the gradient reads the neighbours' heights
  if (size <= 0.0 || weight <= 0.0) return;
  if (lost_only) {  // what the erosion took of it (model 3), as erode.cpp's subtract_fine_detail
    const std::vector<Grid<float>> left = tiled_fine_detail(cut, tiles, detail_levels, exchange);
    for (std::size_t k = 0; k < tiles.size(); ++k)
      for (std::size_t i = 0; i < detail[k].size(); ++i) detail[k].values()[i] -= left[k].values()[i];
  }
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Rect own = cut.owned(tiles[k].tile), halo = cut.haloed(tiles[k].tile);
    const Heightfield before = tiles[k].flow.heights;
    const auto at = [&](int x, int y) { return before(x - halo.x0, y - halo.y0); };
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) {
        const double gradient = gradient_at(at, x, y, cut.width, cut.height, before.cell_size_m);
        tiles[k].flow.heights(x - halo.x0, y - halo.y0) +=
            kept_detail(weight, size, tiles[k].eroded_m(x - own.x0, y - own.y0), detail[k](x - own.x0, y - own.y0),
                        static_cast<double>(at(x, y)) - base_level, gradient);
      }
  }
}

}  // namespace

double tiled_response_time(const TileCut& cut, std::vector<ErodingTile>& tiles, const StreamPowerParams& params, TileExchange& exchange) {
  if (params.erodibility <= 0.0) return std::numeric_limits<double>::infinity();
  const double cell_size = tiles.empty() ? 1.0 : tiles.front().flow.heights.cell_size_m;
  route_in_place(cut, tiles, params.sea_level_m, cell_size, exchange);
  const std::vector<Grid<std::int64_t>> receivers = haloed_receivers(cut, routed_of(tiles), exchange);
  // The water surface of the receivers (n != 1 reads the slope to them).
  std::vector<Grid<float>> surface;
  std::vector<int> ids;
  for (const ErodingTile& t : tiles) {
    const Rect own = cut.owned(t.tile), halo = cut.haloed(t.tile);
    Grid<float> s(halo.width(), halo.height(), 0.0f);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) s(x - halo.x0, y - halo.y0) = t.flow.water_level(x - own.x0, y - own.y0);
    surface.push_back(std::move(s));
    ids.push_back(t.tile);
  }
  std::vector<Grid<float>*> grids;
  grids.reserve(surface.size());
  for (Grid<float>& s : surface) grids.push_back(&s);
  exchange_halo(cut, ids, grids, exchange);

  const AreaPower area_power(cell_size * cell_size, params.area_exponent);
  std::vector<TileCells> cells;
  cells.reserve(tiles.size());
  for (const ErodingTile& t : tiles) cells.emplace_back(cut, t.tile);
  std::vector<std::vector<double>> time(tiles.size());
  for (std::size_t k = 0; k < tiles.size(); ++k) time[k].assign(cells[k].haloed_count(), 0.0);
  std::vector<double> longest(tiles.size(), 0.0);  // per tile: the tiles work at once
  run_wave(cut, ids_of(tiles), receivers, Wave::outlets_first, time, exchange, [&](std::size_t k, int x, int y) {
    const TileCells& c = cells[k];
    const WorldCell i = cut.index(x, y), r = receivers[k](x - c.halo().x0, y - c.halo().y0);
    if (r == i) return 0.0;
    const bool diagonal = is_diagonal(static_cast<CellIndex>(r - i), cut.width);
    const double length = cell_size * (diagonal ? neighbour_distance[1] : 1.0);
    double celerity = params.erodibility * area_power(tiles[k].flow.area_m2(x - c.own().x0, y - c.own().y0));
    if (params.slope_exponent != 1.0) {
      const float here = surface[k](x - c.halo().x0, y - c.halo().y0);
      const float there = surface[k](cut.x_of(r) - c.halo().x0, cut.y_of(r) - c.halo().y0);
      const double slope = std::max(1e-3, (static_cast<double>(here) - there) / length);
      celerity *= std::pow(slope, params.slope_exponent - 1.0);
    }
    const double t = time[k][c.haloed(r)] + length / celerity;
    longest[k] = std::max(longest[k], t);
    return t;
  });
  return exchange.max(longest.empty() ? 0.0 : *std::max_element(longest.begin(), longest.end()));
}

namespace {

/// The droplets' height unit times the cell size, from the mean height step along every 7th row
/// of the whole world (as droplets.cpp measures it). Collective.
float droplet_cell_size(const TileCut& cut, std::vector<ErodingTile>& tiles, TileExchange& exchange) {
  const int width = cut.width;
  exchange_heights_halo(cut, tiles, exchange);  // the height steps read the east neighbour
  std::vector<ExactSum> steps(tiles.size());
  std::vector<std::int64_t> counts(tiles.size(), 0);
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Rect own = cut.owned(tiles[k].tile), halo = cut.haloed(tiles[k].tile);
    for (int y = own.y0; y < own.y1; ++y)
      if (y % 7 == 0)
        for (int x = own.x0; x < own.x1 && x + 1 < width; ++x)
          steps[k].add(height_step(tiles[k].flow.heights(x + 1 - halo.x0, y - halo.y0), tiles[k].flow.heights(x - halo.x0, y - halo.y0))),
              ++counts[k];
  }
  const auto [step_sum, step_count] = exact_total(tiles, steps, counts, cut, exchange);
  const double cell_size_m = tiles.empty() ? 1.0 : tiles.front().flow.heights.cell_size_m;
  return static_cast<float>(cell_size_m * droplet_height_scale(step_sum, step_count, cell_size_m));
}

/// The droplets over the tiles, as droplets.cpp runs them over the whole world: in rounds of
/// droplet_round, each round's droplets bucketed by the droplet tile (DropletTiles) they start
/// in, the droplet tiles run in four colours so that no two running at once reach the same
/// cell. The world tile holding a droplet tile's first cell runs it, on a window of its reach
/// that the other tiles send it, and sends their cells back.
class TiledDropletRun {
 public:
  TiledDropletRun(const TileCut& cut, std::vector<ErodingTile>& tiles, const DropletParams& params, float base_level, float cell_size)
      : cut_(cut),
        tiles_(tiles),
        params_(params),
        layout_(params, cut.width, cut.height),
        base_level_(base_level),
        cell_size_(cell_size),
        by_tile_(static_cast<std::size_t>(layout_.tiles_x) * static_cast<std::size_t>(layout_.tiles_y)) {}

  /// Droplets first .. first + count - 1, run. Collective.
  void run_round(std::int64_t first, std::int64_t count, TileExchange& exchange) {
    for (auto& bucket : by_tile_) bucket.clear();
    for (std::int64_t d = first; d < first + count; ++d) {
      const auto [x, y] = droplet_start(cut_.width, cut_.height, params_, static_cast<std::uint64_t>(d));
      const int tx = std::min(static_cast<int>(x) / layout_.tile, layout_.tiles_x - 1),
                ty = std::min(static_cast<int>(y) / layout_.tile, layout_.tiles_y - 1);
      by_tile_[static_cast<std::size_t>(ty) * layout_.tiles_x + tx].push_back({x, y});
    }
    for (int colour = 0; colour < 4; ++colour) {
      std::vector<TileMessage> incoming = exchange.exchange(cells_to_send(colour));
      incoming = exchange.exchange(run_droplet_tiles(colour, incoming));
      take_cells_back(incoming);
    }
  }

 private:
  struct Start {
    float x, y;
  };

  Rect droplet_rect(int d) const {
    const int dx = d % layout_.tiles_x, dy = d / layout_.tiles_x;
    return Rect{dx * layout_.tile, dy * layout_.tile, std::min(cut_.width, (dx + 1) * layout_.tile),
                std::min(cut_.height, (dy + 1) * layout_.tile)};
  }
  /// The cells droplet tile d's droplets may reach.
  Rect reach_of(int d) const {
    const Rect r = droplet_rect(d);
    return Rect{r.x0 - layout_.reach, r.y0 - layout_.reach, r.x1 + layout_.reach, r.y1 + layout_.reach}.intersect(
        Rect{0, 0, cut_.width, cut_.height});
  }
  /// The world tile that runs droplet tile d.
  int executor(int d) const { return cut_.tile_at(droplet_rect(d).x0, droplet_rect(d).y0); }
  float& cell_of(std::size_t k, int x, int y) {
    const Rect halo = cut_.haloed(tiles_[k].tile);
    return tiles_[k].flow.heights(x - halo.x0, y - halo.y0);
  }
  /// The droplet tiles whose reach overlaps tile k's own cells.
  std::vector<int> droplet_tiles_near(std::size_t k) const {
    const Rect own = cut_.owned(tiles_[k].tile);
    std::vector<int> near;
    const int x0 = std::max(0, (own.x0 - layout_.reach) / layout_.tile),
              x1 = std::min(layout_.tiles_x - 1, (own.x1 - 1 + layout_.reach) / layout_.tile);
    const int y0 = std::max(0, (own.y0 - layout_.reach) / layout_.tile),
              y1 = std::min(layout_.tiles_y - 1, (own.y1 - 1 + layout_.reach) / layout_.tile);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) near.push_back(y * layout_.tiles_x + x);
    return near;
  }
  /// Droplet tile d runs in `colour` and has droplets this round.
  bool active(int d, int colour) const {
    return (d % layout_.tiles_x) % 2 == colour % 2 && (d / layout_.tiles_x) % 2 == colour / 2 &&
           !by_tile_[static_cast<std::size_t>(d)].empty();
  }

  /// Out: each tile's cells within reach of an active droplet tile that another tile runs.
  std::vector<TileMessage> cells_to_send(int colour) {
    std::vector<TileMessage> outgoing;
    for (std::size_t k = 0; k < tiles_.size(); ++k)
      for (int d : droplet_tiles_near(k)) {
        const Rect part = reach_of(d).intersect(cut_.owned(tiles_[k].tile));
        if (!active(d, colour) || part.empty() || executor(d) == tiles_[k].tile) continue;
        std::vector<float> values;
        for (int y = part.y0; y < part.y1; ++y)
          for (int x = part.x0; x < part.x1; ++x) values.push_back(cell_of(k, x, y));
        outgoing.push_back(
            {tiles_[k].tile, executor(d), Packer().put(std::vector<int>{d, part.x0, part.y0, part.x1, part.y1}).put(values).take()});
      }
    return outgoing;
  }

  /// Run: each active droplet tile this rank runs, on its tile's own cells when its reach lies
  /// within them, else on a window of the cells the others sent. Returns their cells, to send back.
  std::vector<TileMessage> run_droplet_tiles(int colour, const std::vector<TileMessage>& incoming) {
    std::vector<TileMessage> outgoing;
    for (std::size_t k = 0; k < tiles_.size(); ++k) {
      const Rect own = cut_.owned(tiles_[k].tile), halo = cut_.haloed(tiles_[k].tile);
      for (int d : droplet_tiles_near(k)) {
        if (!active(d, colour) || executor(d) != tiles_[k].tile) continue;
        if (own.contains(reach_of(d))) {
          const DropletGround ground{tiles_[k].flow.heights.data(), halo.width(), halo.x0, halo.y0, cut_.width, cut_.height};
          run_droplets_of(d, ground);
          continue;
        }
        run_on_window(k, d, incoming, outgoing);
      }
    }
    return outgoing;
  }

  void run_droplets_of(int d, const DropletGround& ground) const {
    for (const Start& start : by_tile_[static_cast<std::size_t>(d)])
      run_droplet(ground, cell_size_, params_, base_level_, start.x, start.y);
  }

  /// Droplet tile d, run by tile k on a window of its reach: tile k's cells and those the
  /// others sent; the cells go back where they came from (tile k's at once, the others' in
  /// `outgoing`).
  void run_on_window(std::size_t k, int d, const std::vector<TileMessage>& incoming, std::vector<TileMessage>& outgoing) {
    const Rect own = cut_.owned(tiles_[k].tile);
    const Rect window = reach_of(d);
    Grid<float> z(window.width(), window.height(), 0.0f);
    const Rect mine = window.intersect(own);
    for (int y = mine.y0; y < mine.y1; ++y)
      for (int x = mine.x0; x < mine.x1; ++x) z(x - window.x0, y - window.y0) = cell_of(k, x, y);
    std::vector<std::pair<int, std::vector<int>>> parts;  // (tile, rectangle) to send back
    for (const TileMessage* m : addressed_to(incoming, tiles_[k].tile)) {
      Unpacker in(m->bytes);
      const std::vector<int> head = in.take<int>();
      if (head.at(0) != d) continue;
      const std::vector<float> values = in.take<float>();
      std::size_t v = 0;
      for (int y = head[2]; y < head[4]; ++y)
        for (int x = head[1]; x < head[3]; ++x) z(x - window.x0, y - window.y0) = values.at(v++);
      parts.push_back({m->from, head});
    }
    run_droplets_of(d, DropletGround{z.data(), window.width(), window.x0, window.y0, cut_.width, cut_.height});
    for (int y = mine.y0; y < mine.y1; ++y)
      for (int x = mine.x0; x < mine.x1; ++x) cell_of(k, x, y) = z(x - window.x0, y - window.y0);
    for (const auto& [to, head] : parts) {
      std::vector<float> values;
      for (int y = head[2]; y < head[4]; ++y)
        for (int x = head[1]; x < head[3]; ++x) values.push_back(z(x - window.x0, y - window.y0));
      outgoing.push_back({tiles_[k].tile, to, Packer().put(head).put(values).take()});
    }
  }

  /// In: the cells other tiles' droplet tiles ran over, back in their tiles.
  void take_cells_back(const std::vector<TileMessage>& incoming) {
    for (std::size_t k = 0; k < tiles_.size(); ++k)
      for (const TileMessage* m : addressed_to(incoming, tiles_[k].tile)) {
        Unpacker in(m->bytes);
        const std::vector<int> head = in.take<int>();
        const std::vector<float> values = in.take<float>();
        std::size_t v = 0;
        for (int y = head[2]; y < head[4]; ++y)
          for (int x = head[1]; x < head[3]; ++x) cell_of(k, x, y) = values.at(v++);
      }
  }

  const TileCut& cut_;
  std::vector<ErodingTile>& tiles_;
  const DropletParams& params_;
  const DropletTiles layout_;
  const float base_level_;
  const float cell_size_;
  std::vector<std::vector<Start>> by_tile_;  // this round's droplets by the droplet tile they start in
};

}  // namespace

void tiled_droplets(const TileCut& cut, std::vector<ErodingTile>& tiles, const DropletParams& params, std::optional<double> base_level_m,
                    TileExchange& exchange) {
  params.validate();
  const int width = cut.width, height = cut.height;
  const std::int64_t droplets = droplet_count(params, static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  if (width < 2 || height < 2 || droplets == 0) return;
  const float base_level = base_level_m ? static_cast<float>(*base_level_m) : -std::numeric_limits<float>::infinity();
  TiledDropletRun run(cut, tiles, params, base_level, droplet_cell_size(cut, tiles, exchange));
  for (std::int64_t first = 0; first < droplets; first += droplet_round)
    run.run_round(first, std::min<std::int64_t>(droplet_round, droplets - first), exchange);
}

namespace {

/// The world's tiles as the chain's surface (erosion_chain.hpp). The fine detail of the heights
/// before the chain is taken at the start: the tiles are eroded in place.
class TiledSurface final : public ErosionSurface {
 public:
  TiledSurface(const TileCut& cut, std::vector<ErodingTile>& tiles, TileExchange& exchange, bool keeps_detail)
      : cut_(cut),
        tiles_(tiles),
        exchange_(exchange),
        cell_size_(tiles.empty() ? 1.0 : tiles.front().flow.heights.cell_size_m),
        detail_(keeps_detail ? tiled_fine_detail(cut, tiles, detail_levels, exchange) : std::vector<Grid<float>>(tiles.size())) {}

  std::size_t cells() const override { return static_cast<std::size_t>(cut_.width) * static_cast<std::size_t>(cut_.height); }
  double cell_size_m() const override { return cell_size_; }

  double response_time_yr(const StreamPowerParams& params, const Context&) override {
    return tiled_response_time(cut_, tiles_, params, exchange_);
  }
  ErosionBudget stream_power_step(const StreamPowerParams& params, const Context&) override {
    return tiled_stream_power_step(cut_, tiles_, params, exchange_);
  }
  void follow_inner_land(double base_level) override { tiled_follow_inner_land(cut_, tiles_, base_level); }
  void thermal(const ThermalParams&, const Context&) override { throw std::logic_error("thermal erosion is not tiled"); }
  void settle() override {
    settled_.clear();
    for (const ErodingTile& t : tiles_) settled_.push_back(own_heights(cut_, t));
  }
  void droplets(const DropletParams& params, std::optional<double> base_level_m, const Context&) override {
    tiled_droplets(cut_, tiles_, params, base_level_m, exchange_);
  }
  void keep_detail(double weight, double base_level, bool lost_only) override {
    tiled_keep_detail(cut_, tiles_, detail_, weight, base_level, lost_only, exchange_);
  }
  void stay_above_settled(double base_level) override {
    for (std::size_t k = 0; k < tiles_.size(); ++k) {
      const Rect own = cut_.owned(tiles_[k].tile), halo = cut_.haloed(tiles_[k].tile);
      for (int y = own.y0; y < own.y1; ++y)
        for (int x = own.x0; x < own.x1; ++x) {
          float& h = tiles_[k].flow.heights(x - halo.x0, y - halo.y0);
          h = std::max(h, settled_floor(settled_[k](x - own.x0, y - own.y0), base_level));
        }
    }
    exchange_heights_halo(cut_, tiles_, exchange_);
  }

 private:
  const TileCut& cut_;
  std::vector<ErodingTile>& tiles_;
  TileExchange& exchange_;
  const double cell_size_;
  const std::vector<Grid<float>> detail_;
  std::vector<Heightfield> settled_;
};

/// tiled_erode for models 2 and 3.
ErosionBudget tiled_erode_as(const TileCut& cut, std::vector<ErodingTile>& tiles, ErosionChainParams params,
                             std::optional<ErosionStage> stage, TileExchange& exchange, const Context& context, int model) {
  params.fluvial.validate();
  params.thermal.validate();
  params.droplets.validate();
  if (params.thermal.iterations > 0) fail("thermal erosion is not tiled yet: a tiled world takes thermal iterations = 0 (the default)");
  if (cut.tile < 2) fail("tiles of {} cells: a tiled erosion takes tiles of at least 2 cells", cut.tile);
  TiledSurface surface(cut, tiles, exchange, params.keep_detail > 0.0);
  if (model < 2) fail("erosion model {} is not tiled: a tiled world takes models 2 to 4 (recipes of version 2 on)", model);
  return run_erosion_chain(surface, params, stage, model, context);
}

/// The own heights of each of the tiles on `wide`, the cut of their world with its margin
/// (edge_margin.hpp): their cells, and where a tile touches the world's edge the margin's cells,
/// reflected from the land within the margin of that edge (a ring of the margin's width around
/// each tile, as extended_past_edges reflects the whole world). Collective.
std::vector<Heightfield> heights_past_edges(const TileCut& cut, const TileCut& wide, const std::vector<ErodingTile>& tiles,
                                            TileExchange& exchange) {
  const int m = wide.margin;
  std::vector<Heightfield> ringed(tiles.size());
  std::vector<int> ids;
  std::vector<Grid<float>*> grids;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Rect own = cut.owned(tiles[k].tile), halo = cut.haloed(tiles[k].tile), ring = cut.haloed(tiles[k].tile, m);
    ringed[k] = Heightfield(ring.width(), ring.height(), 0.0f, tiles[k].flow.heights.cell_size_m);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) ringed[k](x - ring.x0, y - ring.y0) = tiles[k].flow.heights(x - halo.x0, y - halo.y0);
    ids.push_back(tiles[k].tile), grids.push_back(&ringed[k]);
  }
  exchange_halo(cut, ids, grids, exchange, m);
  std::vector<Heightfield> heights;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const Rect own = cut.owned(tiles[k].tile), ring = cut.haloed(tiles[k].tile, m), target = wide.owned(tiles[k].tile);
    const Margins margins{own.x0 == 0 ? m : 0, own.y0 == 0 ? m : 0, own.x1 == cut.width ? m : 0, own.y1 == cut.height ? m : 0};
    const Heightfield extended = extended_past_edges(ringed[k], margins);
    // extended's sample (0, 0) is the wide world's (ring.x0 + m - margins.left, ring.y0 + m - margins.top).
    const int x0 = ring.x0 + m - margins.left, y0 = ring.y0 + m - margins.top;
    Heightfield part(target.width(), target.height(), 0.0f, extended.cell_size_m);
    for (int y = target.y0; y < target.y1; ++y)
      for (int x = target.x0; x < target.x1; ++x) part(x - target.x0, y - target.y0) = extended(x - x0, y - y0);
    heights.push_back(std::move(part));
  }
  return heights;
}

/// The tiles' heights and maps from those of the same tiles on `wide`, their world with its
/// margin: the margin's cells left out. Collective (the halos are exchanged again).
void take_inside_margin(const TileCut& cut, const TileCut& wide, std::vector<ErodingTile>& tiles, const std::vector<ErodingTile>& widened,
                        TileExchange& exchange) {
  const int m = wide.margin;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const int t = tiles[k].tile;
    const Rect own = cut.owned(t), halo = cut.haloed(t), wide_own = wide.owned(t), wide_halo = wide.haloed(t);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) {
        tiles[k].flow.heights(x - halo.x0, y - halo.y0) = widened[k].flow.heights(x + m - wide_halo.x0, y + m - wide_halo.y0);
        tiles[k].eroded_m(x - own.x0, y - own.y0) = widened[k].eroded_m(x + m - wide_own.x0, y + m - wide_own.y0);
        tiles[k].deposited_m(x - own.x0, y - own.y0) = widened[k].deposited_m(x + m - wide_own.x0, y + m - wide_own.y0);
      }
  }
  exchange_heights_halo(cut, tiles, exchange);
}

}  // namespace

ErosionBudget tiled_erode(const TileCut& cut, std::vector<ErodingTile>& tiles, ErosionChainParams params, std::optional<ErosionStage> stage,
                          TileExchange& exchange, const Context& context, int model) {
  if (model >= 4) {  // model 3 on the world with its margin (erode.hpp)
    if (cut.margin != 0) throw std::logic_error("tiled_erode: model 4 adds the margin itself");
    const TileCut wide{cut.width + 2 * edge_margin(std::min(cut.width, cut.height)),
                       cut.height + 2 * edge_margin(std::min(cut.width, cut.height)), cut.tile,
                       edge_margin(std::min(cut.width, cut.height))};
    std::vector<Heightfield> heights = heights_past_edges(cut, wide, tiles, exchange);
    std::size_t next = 0;
    std::vector<ErodingTile> widened = eroding_tiles(wide, tiles.empty() ? 1.0 : tiles.front().flow.heights.cell_size_m, exchange,
                                                     [&](int) { return std::move(heights[next++]); });
    const ErosionBudget budget = tiled_erode_as(wide, widened, params, stage, exchange, context, 3);
    take_inside_margin(cut, wide, tiles, widened, exchange);
    return budget;
  }
  return tiled_erode_as(cut, tiles, params, stage, exchange, context, model);
}

}  // namespace sansui::water

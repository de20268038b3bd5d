// Routing across depressions by the basin graph (Cordonnier, Bovy & Braun 2019): see
// depression_routing.hpp.
#include "water/depression_routing.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "core/parallel_sort.hpp"
#include "water/flow.hpp"

namespace sansui::water {
namespace {

/// The four neighbours ahead in raster order (east, south-east, south, south-west): each cell
/// pair is seen once.
constexpr std::array<int, 4> ahead_dx = {1, 1, 0, -1};
constexpr std::array<int, 4> ahead_dy = {0, 1, 1, 1};

/// Rows per block of the parallel passes over the grid: fixed, so that the work split (and with
/// it nothing of the result) depends on the number of threads.
constexpr int rows_per_block = 16;

/// Basin labels into scratch.basin: 0 for every cell that drains to an outlet, 1.. for the pits
/// in raster order (scratch.pit[b] is the root cell of basin b; pit[0] is unused).
void label_basins(const Heightfield& heights, const Outlets& outlets, const CellIndex* rec, RoutingScratch& scratch) {
  const int width = heights.width(), height = heights.height();
  const int blocks = (height + rows_per_block - 1) / rows_per_block;
  resize_on_huge_pages(scratch.basin, heights.size());
  std::int32_t* label = scratch.basin.data();
  constexpr std::int32_t unlabelled = -1, unnumbered_pit = -2;
  // The roots: outlets are basin 0; pits are counted per block of rows, then numbered in raster
  // order from the counts' running sum.
  std::vector<std::int32_t>& pits_before = scratch.pits_per_block;
  pits_before.assign(static_cast<std::size_t>(blocks) + 1, 0);
  const auto rows_of = [&](int block) { return std::pair{block * rows_per_block, std::min(height, (block + 1) * rows_per_block)}; };
  parallel_for(0, blocks, [&](int block) {
    std::int32_t pits = 0;
    for (auto [y, y_end] = rows_of(block); y < y_end; ++y)
      for (int x = 0; x < width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * width + x;
        if (rec[i] != static_cast<CellIndex>(i))
          label[i] = unlabelled;
        else if (is_outlet(heights, outlets, x, y))
          label[i] = 0;
        else
          label[i] = unnumbered_pit, ++pits;
      }
    pits_before[static_cast<std::size_t>(block) + 1] = pits;
  });
  for (std::size_t b = 0; b < static_cast<std::size_t>(blocks); ++b) pits_before[b + 1] += pits_before[b];
  scratch.pit.assign(static_cast<std::size_t>(pits_before.back()) + 1, -1);
  parallel_for(0, blocks, [&](int block) {
    std::int32_t next = 1 + pits_before[static_cast<std::size_t>(block)];
    auto [y_begin, y_end] = rows_of(block);
    const std::size_t end = static_cast<std::size_t>(y_end) * width;
    for (std::size_t i = static_cast<std::size_t>(y_begin) * width; i < end; ++i)
      if (label[i] == unnumbered_pit) scratch.pit[static_cast<std::size_t>(next)] = static_cast<CellIndex>(i), label[i] = next++;
  });
  // Every other cell takes the label of the root it flows to: walk down to a labelled cell, then
  // label the walked path, so each cell is walked about twice in all. Threads whose walks meet
  // write the same labels, so relaxed atomic reads and writes give one result.
  parallel_for_ranges<std::size_t>(0, heights.size(), std::size_t{1} << 15, [&](std::size_t range_begin, std::size_t range_end) {
    std::vector<CellIndex> path;
    const auto label_of = [label](CellIndex c) { return std::atomic_ref<std::int32_t>(label[c]).load(std::memory_order_relaxed); };
    for (std::size_t i = range_begin; i < range_end; ++i) {
      if (label_of(static_cast<CellIndex>(i)) >= 0) continue;
      auto c = static_cast<CellIndex>(i);
      std::int32_t found = 0;
      while ((found = label_of(c)) < 0) path.push_back(c), c = rec[c];
      for (CellIndex p : path) std::atomic_ref<std::int32_t>(label[p]).store(found, std::memory_order_relaxed);
      path.clear();
    }
  });
}

/// The lowest pass found so far between two basins, in a small open-addressing table that one
/// block of rows fills: most border pairs of a block join the same few basins, so keeping only
/// the lowest per basin pair leaves Kruskal's sort a fraction of them.
class LowestPasses {
 public:
  explicit LowestPasses(std::size_t expected) : slots_(std::bit_ceil(std::max<std::size_t>(expected * 2, 64))) {}

  void offer(std::uint64_t basin_pair, std::uint64_t key) {
    if (2 * used_ >= slots_.size()) grow();
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t s = hash(basin_pair) & mask;; s = (s + 1) & mask) {
      Slot& slot = slots_[s];
      if (slot.pair == basin_pair) {
        slot.key = std::min(slot.key, key);
        return;
      }
      if (slot.pair == empty) {
        slot = {basin_pair, key};
        ++used_;
        return;
      }
    }
  }
  void append_to(std::vector<std::uint64_t>& keys) const {
    for (const Slot& slot : slots_)
      if (slot.pair != empty) keys.push_back(slot.key);
  }

 private:
  static constexpr std::uint64_t empty = ~std::uint64_t{0};
  struct Slot {
    std::uint64_t pair = empty, key = 0;
  };
  static std::size_t hash(std::uint64_t v) { return static_cast<std::size_t>((v * 0x9e3779b97f4a7c15ull) >> 17); }
  void grow() {
    std::vector<Slot> old(slots_.size() * 2);
    old.swap(slots_);
    used_ = 0;
    for (const Slot& slot : old)
      if (slot.pair != empty) offer(slot.pair, slot.key);
  }
  std::vector<Slot> slots_;
  std::size_t used_ = 0;
};

/// The lowest pass between every two neighbouring basins (not both draining to an outlet), as a
/// key (pass height, cell * 4 + direction), sorted: Kruskal's edge order. A pair of basins that
/// meet in several blocks of rows may keep one pass per block; the sort puts the lowest first.
std::vector<std::uint64_t> basin_links(const Heightfield& heights, const std::vector<std::int32_t>& label) {
  const int width = heights.width(), height = heights.height();
  constexpr int rows_per_link_block = 64;
  const int blocks = (height + rows_per_link_block - 1) / rows_per_link_block;
  std::vector<std::vector<std::uint64_t>> found(static_cast<std::size_t>(blocks));
  parallel_for(0, blocks, [&](int block) {
    const float* z = heights.data();
    const int y_end = std::min(height, (block + 1) * rows_per_link_block);
    // About one basin pair per ten cells on rough fractal terrain; the table grows if needed.
    LowestPasses lowest(static_cast<std::size_t>(y_end - block * rows_per_link_block) * static_cast<std::size_t>(width) / 8);
    // Neighbouring cells along a border mostly join the same two basins: the lowest pass of a run
    // of them is kept here and offered to the table once, when the pair changes.
    constexpr std::uint64_t none = ~std::uint64_t{0};
    std::uint64_t run_pair = none, run_key = 0;
    const auto offer = [&](std::size_t i, std::size_t j, std::size_t k) {
      const auto a = static_cast<std::uint32_t>(label[i]), b = static_cast<std::uint32_t>(label[j]);
      if (a == b) return;
      const std::uint64_t pair = std::uint64_t{std::min(a, b)} << 32 | std::max(a, b);
      const std::uint64_t key = std::uint64_t{ordered_bits(std::max(z[i], z[j]))} << 32 | (i * 4 + k);
      if (pair == run_pair) {
        run_key = std::min(run_key, key);
        return;
      }
      if (run_pair != none) lowest.offer(run_pair, run_key);
      run_pair = pair, run_key = key;
    };
    const std::array<std::size_t, 4> ahead = {1, static_cast<std::size_t>(width) + 1, static_cast<std::size_t>(width),
                                              static_cast<std::size_t>(width) - 1};
    const auto offer_checked = [&](int x, int y) {
      for (std::size_t k = 0; k < 4; ++k) {
        const int nx = x + ahead_dx[k], ny = y + ahead_dy[k];
        if (nx < 0 || nx >= width || ny >= height) continue;
        offer(static_cast<std::size_t>(y) * width + x, static_cast<std::size_t>(ny) * width + nx, k);
      }
    };
    std::vector<std::int32_t> border(static_cast<std::size_t>(width));
    for (int y = block * rows_per_link_block; y < y_end; ++y) {
      if (y == height - 1 || width < 3) {
        for (int x = 0; x < width; ++x) offer_checked(x, y);
        continue;
      }
      offer_checked(0, y);
      // Inside, the four neighbours ahead exist, and most cells lie inside one basin with them:
      // the cells on a border are listed first without a branch (a branch on each cell was
      // mispredicted on rough land, where two cells in five lie on a border).
      const std::int32_t* here = label.data() + static_cast<std::ptrdiff_t>(y) * width;
      const std::size_t row_start = static_cast<std::size_t>(y) * width;
      std::size_t count = 0;
      for (int x = 1; x < width - 1; ++x) {
        const std::int32_t* cell = here + x;
        const int differs = static_cast<int>(cell[0] != cell[ahead[0]]) | static_cast<int>(cell[0] != cell[ahead[1]]) |
                            static_cast<int>(cell[0] != cell[ahead[2]]) | static_cast<int>(cell[0] != cell[ahead[3]]);
        border[count] = x;
        count += static_cast<std::size_t>(differs);
      }
      for (std::size_t c = 0; c < count; ++c) {
        const std::size_t i = row_start + static_cast<std::size_t>(border[c]);
        for (std::size_t k = 0; k < 4; ++k) offer(i, i + ahead[k], k);
      }
      offer_checked(width - 1, y);
    }
    if (run_pair != none) lowest.offer(run_pair, run_key);
    lowest.append_to(found[static_cast<std::size_t>(block)]);
  });
  std::size_t total = 0;
  for (const auto& keys : found) total += keys.size();
  std::vector<std::uint64_t> keys;
  keys.reserve(total);
  for (const auto& block : found) keys.insert(keys.end(), block.begin(), block.end());
  // The keys are unique, so any sort gives one order: the same with any number of threads.
  parallel_sort(keys.begin(), keys.end());
  return keys;
}

/// The basins of a routing, as label_basins left them in the scratch.
struct Basins {
  const std::vector<std::int32_t>& label;
  const std::vector<CellIndex>& pit;
};

/// A spanning-tree edge between two basins: the cells on either side of the pass and their basins.
struct Pass {
  CellIndex a, b;
  std::int32_t basin_a, basin_b;
  float height;
};

std::vector<Pass> spanning_passes(const Heightfield& heights, const Basins& basins, const std::vector<std::uint64_t>& keys) {
  const int width = heights.width();
  const std::size_t count = basins.pit.size();
  const auto cells_of = [width](std::uint64_t key) {
    const std::uint64_t pair = key & 0xffffffffu;
    const auto i = static_cast<CellIndex>(pair / 4);
    const std::size_t k = pair % 4;
    return std::pair{i, static_cast<CellIndex>(i + ahead_dy[k] * width + ahead_dx[k])};
  };
  // The basins on either side of every pass, looked up in parallel first: the lookups are
  // scattered over the map, and Kruskal's loop below then reads one array in order.
  std::vector<std::array<std::int32_t, 2>> sides(keys.size());
  parallel_for_ranges<std::size_t>(0, keys.size(), 1 << 14, [&](std::size_t begin, std::size_t end) {
    for (std::size_t e = begin; e < end; ++e) {
      const auto [i, j] = cells_of(keys[e]);
      sides[e] = {basins.label[static_cast<std::size_t>(i)], basins.label[static_cast<std::size_t>(j)]};
    }
  });
  std::vector<std::int32_t> parent(count);
  for (std::size_t b = 0; b < count; ++b) parent[b] = static_cast<std::int32_t>(b);
  const auto find = [&](std::int32_t b) {
    while (parent[static_cast<std::size_t>(b)] != b) {
      parent[static_cast<std::size_t>(b)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(b)])];
      b = parent[static_cast<std::size_t>(b)];
    }
    return b;
  };
  std::vector<Pass> passes;
  passes.reserve(count - 1);
  for (std::size_t e = 0; e < keys.size(); ++e) {
    const std::int32_t ri = find(sides[e][0]), rj = find(sides[e][1]);
    if (ri == rj) continue;
    parent[static_cast<std::size_t>(std::max(ri, rj))] = std::min(ri, rj);
    const auto [i, j] = cells_of(keys[e]);
    passes.push_back({i, j, sides[e][0], sides[e][1], std::max(heights.data()[i], heights.data()[j])});
    if (passes.size() + 1 == count) break;
  }
  return passes;
}

}  // namespace

std::int64_t route_depressions(const Heightfield& heights, const Outlets& outlets, Grid<CellIndex>& receiver, Heightfield& water_level,
                               RoutingScratch& scratch, const Context& context) {
  require_routable_heights(heights);
  d8_receivers(heights, outlets, receiver);
  CellIndex* rec = receiver.data();
  label_basins(heights, outlets, rec, scratch);
  const Basins basins{scratch.basin, scratch.pit};
  const std::size_t count = basins.pit.size();
  ensure_shape(water_level, heights.width(), heights.height());
  copy_placement(water_level, heights);
  const float* ground = heights.data();
  float* water = water_level.data();
  if (count == 1) {
    parallel_for_ranges<std::size_t>(0, heights.size(), 1 << 16, [&](std::size_t range_begin, std::size_t range_end) {
      std::copy(ground + range_begin, ground + range_end, water + range_begin);
    });
    return 0;
  }
  context.check_cancelled();
  const std::vector<Pass> passes = spanning_passes(heights, basins, basin_links(heights, basins.label));
  context.check_cancelled();

  // The tree of basins, walked from the outlets (basin 0): each basin learns the pass to its
  // parent and its water level, the highest pass on the way out.
  std::vector<std::int32_t> first(count + 1, 0);
  for (const Pass& p : passes) {
    ++first[static_cast<std::size_t>(p.basin_a) + 1];
    ++first[static_cast<std::size_t>(p.basin_b) + 1];
  }
  for (std::size_t b = 0; b < count; ++b) first[b + 1] += first[b];
  std::vector<std::int32_t> edges(static_cast<std::size_t>(first[count]));
  {
    std::vector<std::int32_t> fill(first.begin(), first.end() - 1);
    for (std::size_t e = 0; e < passes.size(); ++e) {
      edges[static_cast<std::size_t>(fill[static_cast<std::size_t>(passes[e].basin_a)]++)] = static_cast<std::int32_t>(e);
      edges[static_cast<std::size_t>(fill[static_cast<std::size_t>(passes[e].basin_b)]++)] = static_cast<std::int32_t>(e);
    }
  }
  std::vector<float> level(count, -std::numeric_limits<float>::infinity());
  // Per basin, the pass it spills over: the cell inside it and the cell outside.
  std::vector<std::array<CellIndex, 2>> spill(count, {-1, -1});
  std::vector<char> reached(count, 0);
  std::vector<std::int32_t> queue{0};
  reached[0] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::int32_t from = queue[head];
    for (std::int32_t e = first[static_cast<std::size_t>(from)]; e < first[static_cast<std::size_t>(from) + 1]; ++e) {
      const Pass& p = passes[static_cast<std::size_t>(edges[static_cast<std::size_t>(e)])];
      const bool a_inside = p.basin_a != from;
      const std::int32_t to = a_inside ? p.basin_a : p.basin_b;
      if (reached[static_cast<std::size_t>(to)]) continue;
      reached[static_cast<std::size_t>(to)] = 1;
      level[static_cast<std::size_t>(to)] = std::max(p.height, level[static_cast<std::size_t>(from)]);
      spill[static_cast<std::size_t>(to)] = a_inside ? std::array{p.a, p.b} : std::array{p.b, p.a};
      queue.push_back(to);
    }
  }
  // Carve: reverse the receivers from each basin's pass cell down to its pit, then over the pass.
  // A carve reads and writes only its own basin's cells (receivers inside a basin lead to its
  // pit), so the basins can be carved in any order, in parallel.
  parallel_for_ranges<std::size_t>(1, count, 1 << 10, [&](std::size_t begin, std::size_t end) {
    for (std::size_t b = begin; b < end; ++b) {
      if (!reached[b]) continue;
      CellIndex previous = spill[b][1], cell = spill[b][0];
      for (;;) {
        const CellIndex next = rec[cell];
        rec[cell] = previous;
        if (next == cell) break;
        previous = cell, cell = next;
      }
    }
  });

  parallel_for_ranges<std::size_t>(0, heights.size(), 1 << 16, [&](std::size_t range_begin, std::size_t range_end) {
    for (std::size_t i = range_begin; i < range_end; ++i) water[i] = std::max(ground[i], level[static_cast<std::size_t>(basins.label[i])]);
  });
  return static_cast<std::int64_t>(count - 1);
}

DepressionRouting route_depressions(const Heightfield& heights, const Outlets& outlets, const Context& context) {
  DepressionRouting routing;
  RoutingScratch scratch;
  routing.depressions = route_depressions(heights, outlets, routing.receiver, routing.water_level, scratch, context);
  return routing;
}

}  // namespace sansui::water

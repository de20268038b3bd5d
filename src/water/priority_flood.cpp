// Priority-flood (Barnes, Lehman & Mulla 2014): see priority_flood.hpp.
#include "water/priority_flood.hpp"

#include <array>
#include <bit>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "core/error.hpp"
#include "water/depression_routing.hpp"
#include "water/neighbours.hpp"

namespace sansui::water {
namespace {

/// A monotone priority queue (radix heap, Ahuja, Mehlhorn, Orlin & Tarjan 1990): every key pushed
/// is at least the last key popped, which holds in a priority-flood because a cell enters the heap
/// only above the level of the cell that found it. Keys are the level's bits in order; cells of
/// equal level leave last in, first out. The pop order is a fixed function of the pushes, so the
/// flood is the same on every run. Pushes and pops cost a few bit operations.
class RadixHeap {
 public:
  struct Item {
    std::uint32_t key;
    CellIndex cell;
  };

  bool empty() const { return size_ == 0; }
  void push(float level, CellIndex cell) {
    const std::uint32_t key = ordered_bits(level);
    assert(key >= last_);
    buckets_[bucket_of(key)].push_back({key, cell});
    ++size_;
  }
  CellIndex pop() {
    assert(size_ > 0);
    if (buckets_[0].empty()) {
      std::size_t b = 1;
      while (buckets_[b].empty()) ++b;
      std::uint32_t smallest = std::numeric_limits<std::uint32_t>::max();
      for (const Item& item : buckets_[b]) smallest = std::min(smallest, item.key);
      last_ = smallest;
      for (const Item& item : buckets_[b]) buckets_[bucket_of(item.key)].push_back(item);
      buckets_[b].clear();
    }
    const CellIndex cell = buckets_[0].back().cell;
    buckets_[0].pop_back();
    --size_;
    return cell;
  }

 private:
  std::size_t bucket_of(std::uint32_t key) const { return key == last_ ? 0 : 32 - static_cast<std::size_t>(std::countl_zero(key ^ last_)); }

  std::array<std::vector<Item>, 33> buckets_;
  std::uint32_t last_ = 0;
  std::size_t size_ = 0;
};

/// A FIFO of cells reused between pits: the plain queue of Barnes' improved algorithm.
class PitQueue {
 public:
  bool empty() const { return head_ == cells_.size(); }
  void push(CellIndex cell) { cells_.push_back(cell); }
  CellIndex pop() {
    const CellIndex cell = cells_[head_++];
    if (head_ == cells_.size()) cells_.clear(), head_ = 0;
    return cell;
  }

 private:
  std::vector<CellIndex> cells_;
  std::size_t head_ = 0;
};

/// The next float above a finite v: std::nextafter(v, +inf) without the library call, which
/// dominated the flood's inner loop.
float next_up(float v) {
  if (v == 0.0f) return std::numeric_limits<float>::denorm_min();
  const auto u = std::bit_cast<std::uint32_t>(v);
  return std::bit_cast<float>(v > 0.0f ? u + 1 : u - 1);
}

/// The flood itself: returns the level of every cell.
Heightfield flood_epsilon(const Heightfield& heights, const Outlets& outlets, const Context& context) {
  require_routable_heights(heights);
  const int width = heights.width(), height = heights.height();
  Heightfield level(heights);
  if (width < 3 || height < 3) return level;  // every cell is on the edge
  const float* ground = heights.data();
  float* out = level.data();
  std::vector<std::uint8_t> closed(heights.size(), 0);
  RadixHeap open;
  PitQueue pit;

  // Seeds: every outlet is closed with its own height; only those next to a non-outlet cell
  // can find anything, so only they enter the heap.
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (is_outlet(heights, outlets, x, y)) closed[static_cast<std::size_t>(y) * width + x] = on_edge(x, y, width, height) ? 2 : 1;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      if (!closed[i]) continue;
      bool useful = false;
      for (std::size_t k = 0; k < 8 && !useful; ++k) {
        const int nx = x + neighbour_dx[k], ny = y + neighbour_dy[k];
        useful = nx >= 0 && ny >= 0 && nx < width && ny < height && !closed[static_cast<std::size_t>(ny) * width + nx];
      }
      if (useful) open.push(ground[i], static_cast<CellIndex>(i));
    }

  // Every cell that is not closed lies inside the edge ring, so its neighbours need no bounds
  // check; outlets on the edge are visited with one.
  const auto offsets = neighbour_offsets(width);
  const auto neighbour = [&](CellIndex c, std::size_t k, bool edge) -> CellIndex {
    if (edge) {
      const int nx = c % width + neighbour_dx[k], ny = c / width + neighbour_dy[k];
      if (nx < 0 || ny < 0 || nx >= width || ny >= height) return -1;
    }
    return static_cast<CellIndex>(c + offsets[k]);
  };
  // Climbing cells skip the heap (Zhou, Sun & Fu, "An efficient variant of the Priority-Flood
  // algorithm for filling depressions in raster digital elevation models", Computers &
  // Geosciences 90, 2016): a cell found above the level of the cell that found it keeps its own
  // height, and so does every strictly higher unclosed neighbour of it, whatever else is still
  // open. Such cells are closed by a plain walk; one enters the heap only if it has a lower or
  // equal unclosed neighbour, whose level it may set.
  std::vector<CellIndex> climb;  // a stack: depth first keeps the walk on nearby cells
  std::size_t done = 0;
  const std::size_t report_every = std::size_t{1} << 20;
  const auto visit = [&](CellIndex c) {
    const float spill = next_up(out[c]);
    const bool edge = closed[c] == 2;  // only cells of the edge ring are marked 2
    for (std::size_t k = 0; k < 8; ++k) {
      const CellIndex n = neighbour(c, k, edge);
      if (n < 0 || closed[n]) continue;
      closed[n] = 1;
      if (ground[n] <= spill) {
        out[n] = spill;
        pit.push(n);
      } else {
        climb.push_back(n);
      }
    }
  };
  for (;;) {
    if (!climb.empty()) {
      const CellIndex c = climb.back();
      climb.pop_back();
      bool lower_left = false;
      for (std::size_t k = 0; k < 8; ++k) {
        const auto n = static_cast<CellIndex>(c + offsets[k]);  // c is not on the edge: it was not closed at the start
        if (closed[n]) continue;
        if (ground[n] > ground[c]) {
          closed[n] = 1;
          climb.push_back(n);
        } else {
          lower_left = true;
        }
      }
      if (lower_left) open.push(out[c], c);
    } else if (!pit.empty()) {
      visit(pit.pop());
    } else if (!open.empty()) {
      visit(open.pop());
    } else {
      break;
    }
    if (++done % report_every == 0) {
      context.check_cancelled();
      context.report("priority-flood", std::min(1.0, static_cast<double>(done) / static_cast<double>(heights.size())));
    }
  }
  return level;
}

}  // namespace

Heightfield fill_depressions_epsilon(const Heightfield& heights, const Outlets& outlets, const Context& context) {
  return flood_epsilon(heights, outlets, context);
}

LakeFill fill_depressions_with_lakes(const Heightfield& heights, const Outlets& outlets, const Context& context) {
  return lakes_of(heights, route_depressions(heights, outlets, context).water_level);
}

LakeFill lakes_of(const Heightfield& heights, Heightfield water_level) {
  LakeFill result;
  result.surface = std::move(water_level);
  const int width = heights.width(), height = heights.height();
  result.lake = Grid<std::int32_t>(width, height, 0, heights.cell_size_m);
  copy_placement(result.lake, heights);
  const double cell_area = heights.cell_size_m * heights.cell_size_m;
  // Lakes: connected sets of flooded cells, labelled by a breadth-first walk from each unlabelled
  // flooded cell in raster order. Neighbouring flooded cells always share one level (a higher one
  // would spill into the lower), so one label is one lake surface.
  std::vector<CellIndex> queue;
  const auto flooded = [&](std::size_t i) { return result.surface.data()[i] > heights.data()[i]; };
  for (std::size_t start = 0; start < heights.size(); ++start) {
    if (!flooded(start) || result.lake.data()[start] != 0) continue;
    const auto label = static_cast<std::int32_t>(result.lakes.size() + 1);
    Lake lake{result.surface.data()[start], 0, static_cast<std::int32_t>(start), 0.0};
    queue.assign(1, static_cast<CellIndex>(start));
    result.lake.data()[start] = label;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const CellIndex c = queue[head];
      ++lake.cells;
      lake.volume_m3 += (static_cast<double>(result.surface.data()[c]) - heights.data()[c]) * cell_area;
      const int cx = c % width, cy = c / width;
      for (std::size_t k = 0; k < 8; ++k) {
        const int nx = cx + neighbour_dx[k], ny = cy + neighbour_dy[k];
        if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
        const std::size_t n = static_cast<std::size_t>(ny) * width + nx;
        if (result.lake.data()[n] != 0 || !flooded(n)) continue;
        result.lake.data()[n] = label;
        queue.push_back(static_cast<CellIndex>(n));
      }
    }
    result.lakes.push_back(lake);
  }
  return result;
}

}  // namespace sansui::water

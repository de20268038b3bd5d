// D8 and MFD flow routing (see flow.hpp).
#include "water/flow.hpp"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <limits>
#include <vector>

#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "water/depression_routing.hpp"

namespace sansui::water {

Grid<CellIndex> d8_receivers(const Heightfield& surface, const Outlets& outlets) {
  Grid<CellIndex> receiver;
  d8_receivers(surface, outlets, receiver);
  return receiver;
}

void d8_receivers(const Heightfield& surface, const Outlets& outlets, Grid<CellIndex>& receiver) {
  const int width = surface.width(), height = surface.height();
  ensure_shape(receiver, width, height);
  copy_placement(receiver, surface);
  const auto offsets = neighbour_offsets(width);
  std::array<float, 8> inverse_distance{};
  for (std::size_t k = 0; k < 8; ++k) inverse_distance[k] = static_cast<float>(1.0 / neighbour_distance[k]);
  const double sea = outlets.sea_level_m.value_or(-std::numeric_limits<double>::infinity());
  // Each cell depends only on the surface, so rows split between threads give the same bytes.
  // Neighbour by neighbour along a row (not cell by cell), so the comparisons vectorise.
  parallel_for_ranges<int>(0, height, 64, [&](int rows_begin, int rows_end) {
    const float* z = surface.data();
    std::vector<float> steepest(static_cast<std::size_t>(width));
    std::vector<std::int32_t> best(static_cast<std::size_t>(width));
    for (int y = rows_begin; y < rows_end; ++y) {
      CellIndex* out = receiver.row(y).data();
      const auto row_start = static_cast<CellIndex>(static_cast<std::ptrdiff_t>(y) * width);
      for (int x = 0; x < width; ++x) out[x] = row_start + x;
      if (y == 0 || y == height - 1) continue;  // the edge is an outlet
      const float* centre = z + row_start;
      std::fill(steepest.begin(), steepest.end(), 0.0f);
      std::fill(best.begin(), best.end(), -1);
      for (std::size_t k = 0; k < 8; ++k) {
        const float* other = centre + offsets[k];
        const float inverse = inverse_distance[k];
        const auto kk = static_cast<std::int32_t>(k);
        // Plain local pointers and bound: nothing the stores could alias, so the loop vectorises.
        float* __restrict to_steepest = steepest.data();
        std::int32_t* __restrict to_best = best.data();
        const float* __restrict here = centre;
        const float* __restrict there = other;
        const int last = width - 1;
        for (int x = 1; x < last; ++x) {
          const float drop = (here[x] - there[x]) * inverse;
          const float before = to_steepest[x];
          // The choice as a mask (all ones where steeper; the first neighbour wins a tie): GCC
          // vectorises this form, where a second `steeper ? kk : best` became a branch.
          const std::int32_t steeper = -static_cast<std::int32_t>(drop > before);
          to_steepest[x] = drop > before ? drop : before;
          to_best[x] = (kk & steeper) | (to_best[x] & ~steeper);
        }
      }
      for (int x = 1; x < width - 1; ++x) {
        const std::int32_t k = best[static_cast<std::size_t>(x)];
        // At or below the sea is an outlet (priority_flood.hpp's is_outlet, without its edge test).
        if (k < 0 || static_cast<double>(centre[x]) <= sea) continue;
        out[x] = static_cast<CellIndex>(row_start + x + offsets[static_cast<std::size_t>(k)]);
      }
    }
  });
}

std::vector<CellIndex> receiver_stack(const Grid<CellIndex>& receiver) {
  std::vector<CellIndex> stack;
  RoutingScratch scratch;
  receiver_stack(receiver, stack, scratch);
  return stack;
}

namespace {

/// The eight neighbours in raster order: steps along x and y, and index offsets.
constexpr std::array<int, 8> raster_dx = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr std::array<int, 8> raster_dy = {-1, -1, -1, 0, 0, 1, 1, 1};
std::array<std::ptrdiff_t, 8> raster_offsets(int width) {
  std::array<std::ptrdiff_t, 8> offsets{};
  for (std::size_t k = 0; k < 8; ++k) offsets[k] = static_cast<std::ptrdiff_t>(raster_dy[k]) * width + raster_dx[k];
  return offsets;
}

/// Every cell's donors as a mask: bit k set where raster neighbour k drains into the cell. Rows
/// in parallel, neighbour by neighbour along a row (the comparisons vectorise); the edge's
/// neighbours are checked against the map's bounds.
void donor_masks(const Grid<CellIndex>& receiver, std::vector<std::uint8_t>& mask) {
  const int width = receiver.width(), height = receiver.height();
  resize_on_huge_pages(mask, receiver.size());
  const CellIndex* rec = receiver.data();
  const auto offsets = raster_offsets(width);
  const auto edge_mask = [&](int x, int y) {
    const auto self = static_cast<CellIndex>(static_cast<std::ptrdiff_t>(y) * width + x);
    unsigned m = 0;
    for (std::size_t k = 0; k < 8; ++k) {
      const int nx = x + raster_dx[k], ny = y + raster_dy[k];
      if (nx >= 0 && ny >= 0 && nx < width && ny < height && rec[self + offsets[k]] == self) m |= 1u << k;
    }
    return static_cast<std::uint8_t>(m);
  };
  parallel_for_ranges<int>(0, height, 16, [&](int rows_begin, int rows_end) {
    for (int y = rows_begin; y < rows_end; ++y) {
      const auto row_start = static_cast<std::ptrdiff_t>(y) * width;
      std::uint8_t* __restrict out = mask.data() + row_start;
      const bool inside_row = y > 0 && y < height - 1;
      if (!inside_row) {
        for (int x = 0; x < width; ++x) out[x] = edge_mask(x, y);
        continue;
      }
      out[0] = edge_mask(0, y);
      out[width - 1] = edge_mask(width - 1, y);
      const int last = width - 1;
      for (int x = 1; x < last; ++x) out[x] = 0;
      for (std::size_t k = 0; k < 8; ++k) {
        const CellIndex* __restrict there = rec + row_start + offsets[k];
        const auto bit = static_cast<std::uint8_t>(1u << k);
        const auto self = static_cast<CellIndex>(row_start);
        for (int x = 1; x < last; ++x) out[x] = static_cast<std::uint8_t>(out[x] | (there[x] == self + x ? bit : 0));
      }
    }
  });
}

}  // namespace

void receiver_stack(const Grid<CellIndex>& receiver, std::vector<CellIndex>& stack, RoutingScratch& scratch) {
  const int width = receiver.width(), height = receiver.height();
  const CellIndex* rec = receiver.data();
  // Depth first from each base level in raster order, donors pushed in raster order, so every
  // drainage tree is one run of the stack (stack_pieces splits it there) and a river's cells lie
  // near each other in it. The donors of a cell come from its mask (donor_masks: one byte read
  // per cell instead of eight neighbours' receivers on three rows).
  donor_masks(receiver, scratch.donors);
  const std::uint8_t* donors = scratch.donors.data();
  const auto offsets = raster_offsets(width);
  constexpr int stack_block_rows = 16;
  const int blocks = (height + stack_block_rows - 1) / stack_block_rows;
  scratch.stack_parts.resize(static_cast<std::size_t>(blocks));
  parallel_for(0, blocks, [&](int block) {
    std::vector<CellIndex>& part = scratch.stack_parts[static_cast<std::size_t>(block)];
    part.clear();
    std::vector<CellIndex> todo;
    const auto push_donors = [&](CellIndex c) {
      for (unsigned m = donors[c]; m != 0; m &= m - 1)
        todo.push_back(static_cast<CellIndex>(c + offsets[static_cast<std::size_t>(std::countr_zero(m))]));
    };
    const int y_end = std::min(height, (block + 1) * stack_block_rows);
    for (int y = block * stack_block_rows; y < y_end; ++y)
      for (int x = 0; x < width; ++x) {
        const auto root = static_cast<CellIndex>(static_cast<std::ptrdiff_t>(y) * width + x);
        if (rec[root] != root) continue;
        part.push_back(root);
        push_donors(root);
        while (!todo.empty()) {
          const CellIndex c = todo.back();
          todo.pop_back();
          part.push_back(c);
          push_donors(c);
        }
      }
  });
  std::vector<std::size_t> start(static_cast<std::size_t>(blocks) + 1, 0);
  for (std::size_t b = 0; b < static_cast<std::size_t>(blocks); ++b) start[b + 1] = start[b] + scratch.stack_parts[b].size();
  assert(start.back() == receiver.size());
  resize_on_huge_pages(stack, start.back());
  parallel_for(0, blocks, [&](int block) {
    const std::vector<CellIndex>& part = scratch.stack_parts[static_cast<std::size_t>(block)];
    std::copy(part.begin(), part.end(), stack.begin() + static_cast<std::ptrdiff_t>(start[static_cast<std::size_t>(block)]));
  });
}

std::vector<std::size_t> stack_pieces(const std::vector<CellIndex>& stack, const Grid<CellIndex>& receiver, std::size_t pieces) {
  const CellIndex* rec = receiver.data();
  std::vector<std::size_t> bounds{0};
  for (std::size_t p = 1; p < pieces; ++p) {
    std::size_t k = std::max(bounds.back() + 1, stack.size() * p / pieces);
    while (k < stack.size() && rec[stack[k]] != stack[k]) ++k;  // to the next tree's root
    if (k >= stack.size()) break;
    if (k > bounds.back()) bounds.push_back(k);
  }
  bounds.push_back(stack.size());
  return bounds;
}

Grid<double> d8_drainage_area(const Grid<CellIndex>& receiver, const std::vector<CellIndex>& stack, double cell_size_m) {
  Grid<double> area;
  d8_drainage_area(receiver, stack, cell_size_m, area);
  return area;
}

void d8_drainage_area(const Grid<CellIndex>& receiver, const std::vector<CellIndex>& stack, double cell_size_m, Grid<double>& area) {
  ensure_shape(area, receiver.width(), receiver.height());
  area.cell_size_m = cell_size_m;
  double* a = area.data();
  const CellIndex* rec = receiver.data();
  // Upstream first within each tree; trees are independent, so each sum has one fixed order and
  // the bytes never depend on threads.
  const std::vector<std::size_t> pieces = stack_pieces(stack, receiver);
  parallel_for(std::size_t{0}, pieces.size() - 1, [&](std::size_t p) {
    // Each tree's cells first count themselves (in stack order, so a piece touches only its own
    // trees' memory), then pass their counts down. Counts are whole numbers, exact in a double in
    // any order of sums: a tiled world (tiled_routing.hpp) sums them in another order and must
    // get the same bytes. Times the cell area at the end.
    for (std::size_t k = pieces[p]; k < pieces[p + 1]; ++k) a[stack[k]] = 1.0;
    for (std::size_t k = pieces[p + 1]; k-- > pieces[p];) {
      const CellIndex i = stack[k];
      if (rec[i] != i) a[rec[i]] += a[i];
    }
    const double cell_area = cell_size_m * cell_size_m;
    for (std::size_t k = pieces[p]; k < pieces[p + 1]; ++k) a[stack[k]] *= cell_area;
  });
}

Grid<double> mfd_drainage_area(const Heightfield& surface, const Outlets& outlets, double exponent) {
  const int width = surface.width(), height = surface.height();
  const double cell_area = surface.cell_size_m * surface.cell_size_m;
  Grid<double> area(width, height, cell_area, surface.cell_size_m);
  const float* z = surface.data();
  // Kahn's topological order: a cell passes its area on once every higher neighbour that sends
  // to it has done so. Outlets send nothing.
  std::vector<std::uint8_t> waiting(surface.size(), 0);
  std::vector<std::uint8_t> sends(surface.size(), 0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) sends[static_cast<std::size_t>(y) * width + x] = is_outlet(surface, outlets, x, y) ? 0 : 1;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * width + x;
      if (!sends[i]) continue;
      for (std::size_t k = 0; k < 8; ++k) {
        const std::size_t n = static_cast<std::size_t>(y + neighbour_dy[k]) * width + static_cast<std::size_t>(x + neighbour_dx[k]);
        if (z[n] < z[i]) ++waiting[n];
      }
    }
  std::vector<CellIndex> queue;
  queue.reserve(surface.size());
  for (std::size_t i = 0; i < surface.size(); ++i)
    if (waiting[i] == 0) queue.push_back(static_cast<CellIndex>(i));
  double* a = area.data();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const auto i = static_cast<std::size_t>(queue[head]);
    if (!sends[i]) continue;
    const int x = static_cast<int>(i % static_cast<std::size_t>(width)), y = static_cast<int>(i / static_cast<std::size_t>(width));
    std::array<double, 8> weight{};
    double total = 0.0;
    for (std::size_t k = 0; k < 8; ++k) {
      const std::size_t n = static_cast<std::size_t>(y + neighbour_dy[k]) * width + static_cast<std::size_t>(x + neighbour_dx[k]);
      const double drop = static_cast<double>(z[i]) - z[n];
      if (drop > 0.0) weight[k] = std::pow(drop / (neighbour_distance[k] * surface.cell_size_m), exponent), total += weight[k];
    }
    for (std::size_t k = 0; k < 8; ++k) {
      if (weight[k] == 0.0) continue;
      const std::size_t n = static_cast<std::size_t>(y + neighbour_dy[k]) * width + static_cast<std::size_t>(x + neighbour_dx[k]);
      a[n] += a[i] * (weight[k] / total);
      if (--waiting[n] == 0) queue.push_back(static_cast<CellIndex>(n));
    }
  }
  return area;
}

Grid<std::int32_t> basin_labels(const Grid<CellIndex>& receiver, const std::vector<CellIndex>& stack) {
  Grid<std::int32_t> label(receiver.width(), receiver.height(), 0, receiver.cell_size_m);
  std::int32_t next = 0;
  const CellIndex* rec = receiver.data();
  for (std::size_t i = 0; i < receiver.size(); ++i)
    if (rec[i] == static_cast<CellIndex>(i)) label.data()[i] = ++next;
  for (CellIndex i : stack)
    if (rec[i] != i) label.data()[i] = label.data()[rec[i]];
  return label;
}

FlowRouting route_flow(const Heightfield& heights, const Outlets& outlets, const Context& context) {
  FlowRouting flow;
  RoutingScratch scratch;
  route_flow(heights, outlets, flow, scratch, context);
  return flow;
}

void route_flow(const Heightfield& heights, const Outlets& outlets, FlowRouting& flow, RoutingScratch& scratch, const Context& context) {
  route_depressions(heights, outlets, flow.receiver, flow.surface, scratch, context);
  context.check_cancelled();
  receiver_stack(flow.receiver, flow.stack, scratch);
  d8_drainage_area(flow.receiver, flow.stack, heights.cell_size_m, flow.area_m2);
  copy_placement(flow.area_m2, flow.receiver);
}

}  // namespace sansui::water

// Exact Euclidean feature transform on a grid, in linear time:
//   A. Meijster, J. Roerdink, W. Hesselink, "A general algorithm for computing distance
//   transforms in linear time" (2000), phase 1 (nearest source along columns, two scans); and
//   P. Felzenszwalb, D. Huttenlocher, "Distance transforms of sampled functions" (2012), the
//   lower envelope of parabolas along rows for phase 2, which also tells which source won.
// Columns are scanned row by row (the inner loop runs along memory and vectorises), rows are
// processed in parallel; the result does not depend on the number of threads.
#pragma once

#include <cstdint>
#include <vector>

#include "core/grid.hpp"
#include "core/parallel.hpp"

namespace sansui::contour {

namespace edt_detail {
inline constexpr std::uint16_t no_source = 0xFFFF;
/// Phase 1: for every cell, the row of the nearest source in its column (no_source: none).
void nearest_rows(const Grid<std::uint8_t>& is_source, Grid<std::uint16_t>& rows);
/// Phase 2 on one row: for each x, the column q minimising (x - q)^2 + g(q)^2 (g < 0: no source).
/// `v` and `f` are scratch.
void lower_envelope(const std::int32_t* g, std::int32_t* winner, int n, std::vector<int>& v, std::vector<std::int64_t>& f);
}  // namespace edt_detail

/// Calls visit(x, y, source_x, source_y) for every cell, with the nearest cell (Euclidean
/// distance between centres) where `is_source` is non-zero; source_x = -1 if there is none.
/// Rows are visited in parallel (visit must be safe for that); heights up to 65535.
template <class Visit>
void visit_nearest_sources(const Grid<std::uint8_t>& is_source, Visit&& visit) {
  const int w = is_source.width(), h = is_source.height();
  auto rows = Grid<std::uint16_t>::uninitialized(w, h);
  edt_detail::nearest_rows(is_source, rows);
  parallel_for_ranges<int>(0, h, 16, [&](int range_begin, int range_end) {
    std::vector<std::int32_t> g(static_cast<std::size_t>(w)), winner(static_cast<std::size_t>(w));
    std::vector<int> v;
    std::vector<std::int64_t> f;
    for (int y = range_begin; y < range_end; ++y) {
      const std::uint16_t* r = &rows(0, y);
      for (int x = 0; x < w; ++x) g[static_cast<std::size_t>(x)] = r[x] == edt_detail::no_source ? -1 : std::abs(r[x] - y);
      edt_detail::lower_envelope(g.data(), winner.data(), w, v, f);
      for (int x = 0; x < w; ++x) {
        const int q = winner[static_cast<std::size_t>(x)];
        visit(x, y, q, q < 0 ? -1 : static_cast<int>(r[q]));
      }
    }
  });
}

/// For every cell, the index (y * width + x) of the nearest source cell, or -1 if none.
void nearest_source(const Grid<std::uint8_t>& is_source, Grid<std::int32_t>& nearest);

}  // namespace sansui::contour

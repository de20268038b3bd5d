// Linear-time Euclidean feature transform (Meijster et al. 2000; Felzenszwalb & Huttenlocher
// 2012): see edt.hpp.
#include "contour/edt.hpp"

#include <algorithm>

#include "core/parallel.hpp"

namespace sansui::contour {
namespace edt_detail {

void nearest_rows(const Grid<std::uint8_t>& is_source, Grid<std::uint16_t>& rows) {
  const int w = is_source.width(), h = is_source.height();
  constexpr int block = 1024;  // columns per task
  parallel_for_ranges<int>(0, (w + block - 1) / block, 1, [&](int blocks_begin, int blocks_end) {
    for (int b = blocks_begin; b < blocks_end; ++b) {
      const int x0 = b * block, x1 = std::min(w, x0 + block);
      for (int y = 0; y < h; ++y) {
        const std::uint8_t* s = &is_source(0, y);
        std::uint16_t* o = &rows(0, y);
        const std::uint16_t* above = y > 0 ? &rows(0, y - 1) : nullptr;
        const auto self = static_cast<std::uint16_t>(y);
        for (int x = x0; x < x1; ++x) o[x] = s[x] != 0 ? self : (above != nullptr ? above[x] : no_source);
      }
      for (int y = h - 2; y >= 0; --y) {
        std::uint16_t* o = &rows(0, y);
        const std::uint16_t* below = &rows(0, y + 1);
        for (int x = x0; x < x1; ++x) {
          // The source below wins if there is none above, or it is strictly nearer.
          const int b_row = below[x], a_row = o[x];
          const bool take = b_row != no_source && (a_row == no_source || b_row - y < y - a_row);
          o[x] = take ? static_cast<std::uint16_t>(b_row) : o[x];
        }
      }
    }
  });
}

void lower_envelope(const std::int32_t* g, std::int32_t* winner, int n, std::vector<int>& v, std::vector<std::int64_t>& fv) {
  v.resize(static_cast<std::size_t>(n));
  fv.resize(static_cast<std::size_t>(n));
  // Where the parabolas of columns p < q cross is (f(q) - f(p)) / (2 (q - p)), f(q) = g(q)^2 + q^2.
  // Crossings are compared cross-multiplied, exactly in integers (f < 2^31 and column gaps
  // < 2^15 for grids up to 32768 samples a side, so products stay below 2^46).
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (g[q] < 0) continue;  // no source in this column: no parabola
    const std::int64_t fq = static_cast<std::int64_t>(g[q]) * g[q] + static_cast<std::int64_t>(q) * q;
    // Drop the last parabola while q's crosses it no later than it crossed the one before.
    while (k >= 1) {
      const auto top = static_cast<std::size_t>(k);
      const int a = v[top], b = v[top - 1];
      if ((fq - fv[top]) * (a - b) > (fv[top] - fv[top - 1]) * (q - a)) break;
      --k;
    }
    ++k;
    v[static_cast<std::size_t>(k)] = q, fv[static_cast<std::size_t>(k)] = fq;
  }
  if (k < 0) {
    std::fill(winner, winner + n, -1);
    return;
  }
  // Parabola j wins from where it crosses parabola j - 1 (the first x above that crossing).
  int x = 0;
  for (int j = 0; j <= k; ++j) {
    int end = n;
    if (j < k) {
      const auto at = static_cast<std::size_t>(j);
      const std::int64_t rise = fv[at + 1] - fv[at], run = 2 * static_cast<std::int64_t>(v[at + 1] - v[at]);
      // floor(rise / run) + 1, rounding toward minus infinity for negative rises.
      const std::int64_t crossing = rise >= 0 ? rise / run : -((-rise + run - 1) / run);
      end = static_cast<int>(std::clamp<std::int64_t>(crossing + 1, x, n));
    }
    std::fill(winner + x, winner + end, v[static_cast<std::size_t>(j)]);
    x = end;
  }
}

}  // namespace edt_detail

void nearest_source(const Grid<std::uint8_t>& is_source, Grid<std::int32_t>& nearest) {
  const int w = is_source.width();
  if (nearest.width() != w || nearest.height() != is_source.height()) nearest = Grid<std::int32_t>::uninitialized(w, is_source.height());
  visit_nearest_sources(is_source, [&](int x, int y, int sx, int sy) { nearest(x, y) = sx < 0 ? -1 : sy * w + sx; });
}

}  // namespace sansui::contour

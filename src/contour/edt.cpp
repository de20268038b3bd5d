// Linear-time Euclidean feature transform (Meijster et al. 2000; Felzenszwalb & Huttenlocher
// 2012): see edt.hpp.
#include "contour/edt.hpp"

#include <algorithm>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace sansui::contour {
namespace {

/// Phase 2 on one row: for each x, the column q minimising (x - q)^2 + g(q)^2 (g < 0: none).
void lower_envelope(const std::int32_t* g, std::int32_t* winner, int n, std::vector<int>& v, std::vector<double>& z) {
  v.resize(static_cast<std::size_t>(n));
  z.resize(static_cast<std::size_t>(n) + 1);
  int k = -1;
  auto f = [&](int q) { return static_cast<double>(g[q]) * g[q] + static_cast<double>(q) * q; };
  auto meet = [&](int q, int p) { return (f(q) - f(p)) / (2.0 * (q - p)); };  // where the parabolas cross
  for (int q = 0; q < n; ++q) {
    if (g[q] < 0) continue;  // no source in this column: no parabola
    if (k < 0) {
      k = 0;
      v[0] = q;
      z[0] = -1e300;
      z[1] = 1e300;
      continue;
    }
    double s = meet(q, v[static_cast<std::size_t>(k)]);
    while (s <= z[static_cast<std::size_t>(k)]) {  // stops at k = 0, where z = -infinity
      --k;
      s = meet(q, v[static_cast<std::size_t>(k)]);
    }
    ++k;
    v[static_cast<std::size_t>(k)] = q;
    z[static_cast<std::size_t>(k)] = s;
    z[static_cast<std::size_t>(k) + 1] = 1e300;
  }
  if (k < 0) {
    std::fill(winner, winner + n, -1);
    return;
  }
  int j = 0;
  for (int x = 0; x < n; ++x) {
    while (z[static_cast<std::size_t>(j) + 1] < x) ++j;
    winner[x] = v[static_cast<std::size_t>(j)];
  }
}

}  // namespace

void nearest_source(const Grid<std::uint8_t>& is_source, Grid<std::int32_t>& nearest) {
  const int w = is_source.width(), h = is_source.height();
  if (nearest.width() != w || nearest.height() != h) nearest = Grid<std::int32_t>::uninitialized(w, h);
  // Phase 1: the nearest source row in each column (-1: none), in blocks of columns.
  constexpr int block = 512;
  tbb::parallel_for(tbb::blocked_range<int>(0, (w + block - 1) / block), [&](const tbb::blocked_range<int>& blocks) {
    for (int b = blocks.begin(); b < blocks.end(); ++b) {
      const int x0 = b * block, x1 = std::min(w, x0 + block);
      for (int y = 0; y < h; ++y) {
        const std::uint8_t* s = &is_source(0, y);
        std::int32_t* o = &nearest(0, y);
        const std::int32_t* above = y > 0 ? &nearest(0, y - 1) : nullptr;
        for (int x = x0; x < x1; ++x) o[x] = s[x] != 0 ? y : (above != nullptr ? above[x] : -1);
      }
      for (int y = h - 2; y >= 0; --y) {
        std::int32_t* o = &nearest(0, y);
        const std::int32_t* below = &nearest(0, y + 1);
        for (int x = x0; x < x1; ++x) {
          const std::int32_t b_row = below[x];
          if (b_row >= 0 && (o[x] < 0 || b_row - y < y - o[x])) o[x] = b_row;
        }
      }
    }
  });
  // Phase 2: along rows, with g = distance to the column's nearest source.
  tbb::parallel_for(tbb::blocked_range<int>(0, h, 16), [&](const tbb::blocked_range<int>& rows) {
    std::vector<std::int32_t> g(static_cast<std::size_t>(w)), source_row(static_cast<std::size_t>(w)), winner(static_cast<std::size_t>(w));
    std::vector<int> v;
    std::vector<double> z;
    for (int y = rows.begin(); y < rows.end(); ++y) {
      std::int32_t* o = &nearest(0, y);
      for (int x = 0; x < w; ++x) {
        source_row[static_cast<std::size_t>(x)] = o[x];
        g[static_cast<std::size_t>(x)] = o[x] < 0 ? -1 : std::abs(o[x] - y);
      }
      lower_envelope(g.data(), winner.data(), w, v, z);
      for (int x = 0; x < w; ++x) {
        const int q = winner[static_cast<std::size_t>(x)];
        o[x] = q < 0 ? -1 : source_row[static_cast<std::size_t>(q)] * w + q;
      }
    }
  });
}

}  // namespace sansui::contour

// Linear-time Euclidean feature transform (Meijster et al. 2000; Felzenszwalb & Huttenlocher
// 2012): see edt.hpp.
#include "contour/edt.hpp"

#include <algorithm>

namespace sansui::contour {
namespace edt_detail {

void nearest_rows(const Grid<std::uint8_t>& is_source, Grid<std::uint16_t>& rows) {
  const int w = is_source.width(), h = is_source.height();
  constexpr int block = 1024;  // columns per task
  tbb::parallel_for(tbb::blocked_range<int>(0, (w + block - 1) / block), [&](const tbb::blocked_range<int>& blocks) {
    for (int b = blocks.begin(); b < blocks.end(); ++b) {
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

void lower_envelope(const std::int32_t* g, std::int32_t* winner, int n, std::vector<int>& v, std::vector<double>& z) {
  v.resize(static_cast<std::size_t>(n));
  z.resize(static_cast<std::size_t>(n) + 1);
  int k = -1;
  // Exact in integers: g^2 + q^2 < 2^31 for grids up to 32768 samples a side.
  auto f = [&](int q) { return static_cast<std::int64_t>(g[q]) * g[q] + static_cast<std::int64_t>(q) * q; };
  auto meet = [&](int q, int p) { return static_cast<double>(f(q) - f(p)) / (2.0 * (q - p)); };  // where the parabolas cross
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

}  // namespace edt_detail

void nearest_source(const Grid<std::uint8_t>& is_source, Grid<std::int32_t>& nearest) {
  const int w = is_source.width();
  if (nearest.width() != w || nearest.height() != is_source.height()) nearest = Grid<std::int32_t>::uninitialized(w, is_source.height());
  visit_nearest_sources(is_source, [&](int x, int y, int sx, int sy) { nearest(x, y) = sx < 0 ? -1 : sy * w + sx; });
}

}  // namespace sansui::contour

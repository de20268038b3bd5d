// Land past the map's edge: see edge_margin.hpp.
#include "water/edge_margin.hpp"

#include <algorithm>
#include <cassert>

#include "core/parallel.hpp"

namespace sansui::water {

int edge_margin(int samples) {
  return std::clamp(samples - 1, 0, edge_margin_cells);
}

Heightfield extended_past_edges(const Heightfield& heights, Margins m) {
  const int width = heights.width(), height = heights.height();
  assert(std::max(m.left, m.right) < std::max(width, 1) && std::max(m.top, m.bottom) < std::max(height, 1));
  Heightfield out = Heightfield::uninitialized(width + m.left + m.right, height + m.top + m.bottom, heights.cell_size_m);
  out.origin_x_m = heights.origin_x_m - m.left * heights.cell_size_m;
  out.origin_y_m = heights.origin_y_m - m.top * heights.cell_size_m;
  // Through the edge sample e of a line: inside at e + k, reflected to e - k.
  const auto reflect = [](float edge, float inside) { return 2.0f * edge - inside; };
  parallel_for(0, height, [&](int y) {
    const float* in = &heights(0, y);
    float* row = &out(m.left, y + m.top);
    std::copy_n(in, width, row);
    for (int k = 1; k <= m.left; ++k) row[-k] = reflect(in[0], in[k]);
    for (int k = 1; k <= m.right; ++k) row[width - 1 + k] = reflect(in[width - 1], in[width - 1 - k]);
  });
  const int top = m.top, bottom = m.top + height - 1;
  for (int x = 0; x < out.width(); ++x) {
    for (int k = 1; k <= m.top; ++k) out(x, top - k) = reflect(out(x, top), out(x, top + k));
    for (int k = 1; k <= m.bottom; ++k) out(x, bottom + k) = reflect(out(x, bottom), out(x, bottom - k));
  }
  return out;
}

Grid<float> inside_margins(const Grid<float>& grid, int margin_x, int margin_y) {
  const int width = grid.width() - 2 * margin_x, height = grid.height() - 2 * margin_y;
  Grid<float> out = Grid<float>::uninitialized(width, height, grid.cell_size_m);
  out.origin_x_m = grid.origin_x_m + margin_x * grid.cell_size_m;
  out.origin_y_m = grid.origin_y_m + margin_y * grid.cell_size_m;
  parallel_for(0, height, [&](int y) { std::copy_n(&grid(margin_x, y + margin_y), width, &out(0, y)); });
  return out;
}

}  // namespace sansui::water

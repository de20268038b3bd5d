// Rectangular cells to square ones: see square_cells.hpp.
#include "io/square_cells.hpp"

#include <algorithm>
#include <cmath>

namespace sansui::io::detail {

Heightfield resample_to_square_cells(const Heightfield& heights, double cell_x_m, double cell_y_m) {
  const double cell = std::min(cell_x_m, cell_y_m);
  const double width_m = (heights.width() - 1) * cell_x_m, height_m = (heights.height() - 1) * cell_y_m;
  const int width = static_cast<int>(std::floor(width_m / cell + 1e-9)) + 1;
  const int height = static_cast<int>(std::floor(height_m / cell + 1e-9)) + 1;
  auto out = Heightfield::uninitialized(width, height, cell);
  out.origin_x_m = heights.origin_x_m;
  out.origin_y_m = heights.origin_y_m;
  const int last_x = heights.width() - 1, last_y = heights.height() - 1;
  for (int j = 0; j < height; ++j) {
    const double v = std::min(j * cell / cell_y_m, static_cast<double>(last_y));
    const int y0 = std::min(static_cast<int>(v), std::max(last_y - 1, 0));
    const int y1 = std::min(y0 + 1, last_y);
    const double fy = v - y0;
    for (int i = 0; i < width; ++i) {
      const double u = std::min(i * cell / cell_x_m, static_cast<double>(last_x));
      const int x0 = std::min(static_cast<int>(u), std::max(last_x - 1, 0));
      const int x1 = std::min(x0 + 1, last_x);
      const double fx = u - x0;
      const double top = heights(x0, y0) + fx * (heights(x1, y0) - heights(x0, y0));
      const double bottom = heights(x0, y1) + fx * (heights(x1, y1) - heights(x0, y1));
      out(i, j) = static_cast<float>(top + fy * (bottom - top));
    }
  }
  return out;
}

}  // namespace sansui::io::detail

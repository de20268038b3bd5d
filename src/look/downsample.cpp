#include "look/downsample.hpp"

#include <algorithm>
#include <cassert>

#include "core/parallel.hpp"

namespace sansui::look {

int downsample_step(int width, int height, int max_samples) {
  assert(max_samples >= 2);
  const int longest = std::max(width, height) - 1, shortest = std::min(width, height) - 1;
  return std::max(1, std::min((longest + max_samples - 2) / (max_samples - 1), shortest));
}

Heightfield downsample(const Heightfield& heights, int step) {
  assert(step >= 1 && !heights.empty());
  if (step == 1) return heights;
  const int out_width = (heights.width() - 1) / step + 1;
  const int out_height = (heights.height() - 1) / step + 1;
  auto out = Heightfield::uninitialized(out_width, out_height, heights.cell_size_m * step);
  out.origin_x_m = heights.origin_x_m;
  out.origin_y_m = heights.origin_y_m;
  const int radius = step / 2;
  parallel_for(0, out_height, [&](int oy) {
    const int y0 = std::max(0, oy * step - radius), y1 = std::min(heights.height() - 1, oy * step + radius);
    for (int ox = 0; ox < out_width; ++ox) {
      const int x0 = std::max(0, ox * step - radius), x1 = std::min(heights.width() - 1, ox * step + radius);
      double sum = 0.0;
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) sum += heights(x, y);
      out(ox, oy) = static_cast<float>(sum / ((x1 - x0 + 1) * (y1 - y0 + 1)));
    }
  });
  return out;
}

}  // namespace sansui::look

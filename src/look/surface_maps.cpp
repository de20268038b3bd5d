#include "look/surface_maps.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/parallel.hpp"
#include "core/random.hpp"

namespace sansui::look {

std::vector<float> height_and_gradient_texels(const Heightfield& heights) {
  const int width = heights.width(), height = heights.height();
  assert(width >= 2 && height >= 2);
  std::vector<float> texels(heights.size() * 4);
  const double cell = heights.cell_size_m;
  parallel_for(0, height, [&](int y) {
    const int north = std::max(y - 1, 0), south = std::min(y + 1, height - 1);
    for (int x = 0; x < width; ++x) {
      const int west = std::max(x - 1, 0), east = std::min(x + 1, width - 1);
      float* texel = &texels[(static_cast<std::size_t>(y) * width + x) * 4];
      texel[0] = heights(x, y);
      texel[1] = static_cast<float>((heights(east, y) - heights(west, y)) / ((east - west) * cell));
      texel[2] = static_cast<float>((heights(x, south) - heights(x, north)) / ((south - north) * cell));
      texel[3] = 0.0f;
    }
  });
  return texels;
}

std::vector<std::uint8_t> tileable_noise_texels(int size, std::uint64_t seed) {
  assert(size >= 16 && (size & (size - 1)) == 0);
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(size) * size * 2);
  // Octave k has 4 * 2^k lattice cells per tile; lattice indices wrap, so the tile repeats.
  auto value_noise = [&](int channel, int octave, double x, double y) {
    const int cells = 4 << octave;
    const double fx = x * cells, fy = y * cells;
    const int ix = static_cast<int>(std::floor(fx)), iy = static_cast<int>(std::floor(fy));
    const double tx = fx - ix, ty = fy - iy;
    const double sx = tx * tx * (3.0 - 2.0 * tx), sy = ty * ty * (3.0 - 2.0 * ty);
    auto lattice = [&](int i, int j) {
      return rng::uniform(seed, static_cast<std::uint64_t>(channel * 16 + octave), ((i % cells) + cells) % cells,
                          ((j % cells) + cells) % cells);
    };
    const double top = lattice(ix, iy) + (lattice(ix + 1, iy) - lattice(ix, iy)) * sx;
    const double bottom = lattice(ix, iy + 1) + (lattice(ix + 1, iy + 1) - lattice(ix, iy + 1)) * sx;
    return top + (bottom - top) * sy;
  };
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int channel = 0; channel < 2; ++channel) {
        double sum = 0.0, amplitude = 0.5;
        for (int octave = 0; octave < 4; ++octave) {
          sum += amplitude * value_noise(channel, octave, (x + 0.5) / size, (y + 0.5) / size);
          amplitude *= 0.5;
        }
        // Stretch the fbm's narrow spread (it clusters around 0.5) over the byte range.
        const double stretched = std::clamp(0.5 + (sum / 0.9375 - 0.5) * 1.8, 0.0, 1.0);
        texels[(static_cast<std::size_t>(y) * size + x) * 2 + channel] = static_cast<std::uint8_t>(std::lround(stretched * 255.0));
      }
  return texels;
}

std::vector<std::uint8_t> band_noise_texels(int width, int height, double extent_x, double extent_y) {
  assert(width >= 2 && height >= 2);
  constexpr int tile = 256;
  static_assert((tile & (tile - 1)) == 0);
  const std::vector<std::uint8_t> noise = tileable_noise_texels(tile);
  // Bilinear lookup in the repeating tile, at texel coordinates (x, y).
  auto lookup = [&](int channel, double x, double y) {
    const double fx = std::floor(x - 0.5), fy = std::floor(y - 0.5);
    const double tx = x - 0.5 - fx, ty = y - 0.5 - fy;
    const int x0 = static_cast<int>(fx) & (tile - 1), y0 = static_cast<int>(fy) & (tile - 1);
    const int x1 = (x0 + 1) & (tile - 1), y1 = (y0 + 1) & (tile - 1);
    auto at = [&](int xx, int yy) { return static_cast<double>(noise[(static_cast<std::size_t>(yy) * tile + xx) * 2 + channel]); };
    const double top = at(x0, y0) + (at(x1, y0) - at(x0, y0)) * tx;
    const double bottom = at(x0, y1) + (at(x1, y1) - at(x0, y1)) * tx;
    return top + (bottom - top) * ty;
  };
  constexpr double wander_scale = 0.9, patch_scale = 7.0;  // repeats of the tile per terrain size
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(width) * height * 2);
  parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const double px = extent_x * x / (width - 1), py = extent_y * y / (height - 1);
      const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 2;
      texels[i] = static_cast<std::uint8_t>(std::lround(lookup(0, px * wander_scale * tile, py * wander_scale * tile)));
      texels[i + 1] = static_cast<std::uint8_t>(std::lround(lookup(1, px * patch_scale * tile, py * patch_scale * tile)));
    }
  });
  return texels;
}

}  // namespace sansui::look

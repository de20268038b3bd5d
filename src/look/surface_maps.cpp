#include "look/surface_maps.hpp"

#include <algorithm>
#include <cassert>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>

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
      // Curvature at the texel's own scale: the mean of the eight neighbours minus the sample,
      // per cell size (positive in hollows), for the ground colour's finest landforms.
      const float* above = heights.row(north).data();
      const float* here = heights.row(y).data();
      const float* below = heights.row(south).data();
      const float around = above[west] + above[x] + above[east] + here[west] + here[east] + below[west] + below[x] + below[east];
      texel[3] = static_cast<float>((around / 8.0 - here[x]) / cell);
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

std::vector<std::uint8_t> world_noise_texels(int width, int height, double spacing_m, double origin_x_m, double origin_y_m,
                                             std::uint64_t seed) {
  assert(width >= 2 && height >= 2 && spacing_m > 0.0);
  // Value noise on an unbounded lattice of `wavelength_m` cells: nothing repeats. Along a row the
  // lattice cell changes only every few samples, so each octave keeps its four corners (hashing
  // them is the cost).
  struct Octave {
    std::uint64_t stream;
    double wavelength_m;
    std::int32_t i = INT32_MIN, j = INT32_MIN;
    double c00 = 0, c10 = 0, c01 = 0, c11 = 0;
  };
  auto value_noise = [&](Octave& o, double x_m, double y_m) {
    const double fx = x_m / o.wavelength_m, fy = y_m / o.wavelength_m;
    const double ix = std::floor(fx), iy = std::floor(fy);
    const double tx = fx - ix, ty = fy - iy;
    const double sx = tx * tx * (3.0 - 2.0 * tx), sy = ty * ty * (3.0 - 2.0 * ty);
    const auto i = static_cast<std::int32_t>(ix), j = static_cast<std::int32_t>(iy);
    if (i != o.i || j != o.j) {
      o.i = i, o.j = j;
      o.c00 = rng::uniform(seed, o.stream, i, j), o.c10 = rng::uniform(seed, o.stream, i + 1, j);
      o.c01 = rng::uniform(seed, o.stream, i, j + 1), o.c11 = rng::uniform(seed, o.stream, i + 1, j + 1);
    }
    const double top = o.c00 + (o.c10 - o.c00) * sx, bottom = o.c01 + (o.c11 - o.c01) * sx;
    return top + (bottom - top) * sy;
  };
  // Five octaves each: the band borders wander over kilometres, the patches over tens of metres.
  constexpr int octaves = 5;
  auto fbm = [&](Octave* row, double x_m, double y_m) {
    double sum = 0.0, amplitude = 0.5, total = 0.0;
    for (int octave = 0; octave < octaves; ++octave) {
      // Below about two samples an octave would only alias: leave it out.
      sum += amplitude * (row[octave].wavelength_m >= 2.0 * spacing_m ? value_noise(row[octave], x_m, y_m) : 0.5);
      total += amplitude;
      amplitude *= 0.55;
    }
    return std::clamp(0.5 + (sum / total - 0.5) * 2.2, 0.0, 1.0);
  };
  // Evaluated every `step` samples and filled in bilinearly between (the finest octave spans at
  // least three of those).
  const int step = 38.0 / spacing_m >= 3.0 ? 2 : 1;
  const int cw = (width - 1) / step + 2, ch = (height - 1) / step + 2;
  std::vector<float> coarse(static_cast<std::size_t>(cw) * ch * 2);
  parallel_for(0, ch, [&](int j) {
    Octave rows[2][octaves];
    for (int c = 0; c < 2; ++c)
      for (int octave = 0; octave < octaves; ++octave)
        rows[c][octave] = Octave{static_cast<std::uint64_t>(c * 16 + octave), (c == 0 ? 3000.0 : 600.0) / (1 << octave)};
    for (int i = 0; i < cw; ++i) {
      const double px = origin_x_m + spacing_m * step * i, py = origin_y_m + spacing_m * step * j;
      const std::size_t k = (static_cast<std::size_t>(j) * cw + i) * 2;
      coarse[k] = static_cast<float>(fbm(rows[0], px, py));
      coarse[k + 1] = static_cast<float>(fbm(rows[1], px, py));
    }
  });
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(width) * height * 2);
  parallel_for(0, height, [&](int y) {
    const int j = y / step;
    const float ty = static_cast<float>(y - j * step) / static_cast<float>(step);
    for (int x = 0; x < width; ++x) {
      const int i = x / step;
      const float tx = static_cast<float>(x - i * step) / static_cast<float>(step);
      for (int c = 0; c < 2; ++c) {
        auto at = [&](int a, int b) { return coarse[(static_cast<std::size_t>(b) * cw + a) * 2 + c]; };
        const float top = at(i, j) + (at(i + 1, j) - at(i, j)) * tx, bottom = at(i, j + 1) + (at(i + 1, j + 1) - at(i, j + 1)) * tx;
        texels[(static_cast<std::size_t>(y) * width + x) * 2 + c] =
            static_cast<std::uint8_t>(std::lround(255.0f * (top + (bottom - top) * ty)));
      }
    }
  });
  return texels;
}

Grid<float> signed_water_depth(const Grid<float>& depth, const Heightfield& surface) {
  Grid<float> out(depth.width(), depth.height(), dry_water_depth_m);
  const bool same = surface.width() == depth.width() && surface.height() == depth.height();
  parallel_for(0, depth.height(), [&](int y) {
    for (int x = 0; x < depth.width(); ++x) {
      if (depth(x, y) > 0.0f || !same) {
        out(x, y) = depth(x, y) > 0.0f ? depth(x, y) : dry_water_depth_m;
        continue;
      }
      float level = std::numeric_limits<float>::infinity();
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= depth.width() || ny >= depth.height() || depth(nx, ny) <= 0.0f) continue;
          level = std::min(level, surface(nx, ny));
        }
      if (std::isfinite(level)) out(x, y) = std::clamp(level - surface(x, y), dry_water_depth_m, -1e-3f);
    }
  });
  return out;
}

}  // namespace sansui::look

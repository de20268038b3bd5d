#include "look/ground_maps.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include "core/parallel.hpp"
#include "core/random.hpp"
#include "water/flow.hpp"

namespace sansui::look {
namespace {

/// Mean over a (2r + 1)-wide window along rows, then along columns, the window clamped at the
/// edges (running sums: O(samples) whatever the radius).
Grid<float> box_blur(const Grid<float>& in, int radius) {
  const int w = in.width(), h = in.height();
  Grid<float> rows(w, h, 0.0f), out(w, h, 0.0f);
  parallel_for(0, h, [&](int y) {
    double sum = 0.0;
    int count = 0;
    for (int x = 0; x <= std::min(radius, w - 1); ++x) sum += in(x, y), ++count;
    for (int x = 0; x < w; ++x) {
      rows(x, y) = static_cast<float>(sum / count);
      if (x + radius + 1 < w) sum += in(x + radius + 1, y), ++count;
      if (x - radius >= 0) sum -= in(x - radius, y), --count;
    }
  });
  parallel_for(0, w, [&](int x) {
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y <= std::min(radius, h - 1); ++y) sum += rows(x, y), ++count;
    for (int y = 0; y < h; ++y) {
      out(x, y) = static_cast<float>(sum / count);
      if (y + radius + 1 < h) sum += rows(x, y + radius + 1), ++count;
      if (y - radius >= 0) sum -= rows(x, y - radius), --count;
    }
  });
  return out;
}

/// The largest value within `radius` samples along rows, then columns (a square window).
Grid<float> dilate(const Grid<float>& in, int radius) {
  const int w = in.width(), h = in.height();
  Grid<float> rows(w, h, 0.0f), out(w, h, 0.0f);
  parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      float m = in(x, y);
      for (int k = std::max(0, x - radius); k <= std::min(w - 1, x + radius); ++k) m = std::max(m, in(k, y));
      rows(x, y) = m;
    }
  });
  parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      float m = rows(x, y);
      for (int k = std::max(0, y - radius); k <= std::min(h - 1, y + radius); ++k) m = std::max(m, rows(x, k));
      out(x, y) = m;
    }
  });
  return out;
}

/// Two box blurs: a tent filter, smooth enough that the bilinear texture shows no blocks.
Grid<float> smooth(const Grid<float>& in, int radius) {
  return radius < 1 ? in : box_blur(box_blur(in, radius), radius);
}

std::uint8_t unit_byte(double value) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
}
std::uint8_t signed_byte(double value) {
  return static_cast<std::uint8_t>(std::lround(128.0 + 127.0 * std::clamp(value, -1.0, 1.0)));
}

double slope_deg_at(const Heightfield& heights, int x, int y) {
  const int w = heights.width(), h = heights.height();
  const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, w - 1), y0 = std::max(y - 1, 0), y1 = std::min(y + 1, h - 1);
  const double dx = (heights(x1, y) - heights(x0, y)) / ((x1 - x0) * heights.cell_size_m);
  const double dy = (heights(x, y1) - heights(x, y0)) / ((y1 - y0) * heights.cell_size_m);
  return std::atan(std::hypot(dx, dy)) * 180.0 / std::numbers::pi;
}

/// Curvature at `radius` samples, -1 (convex, a ridge) .. 1 (concave, a valley floor): the
/// position index divided by the radius in metres, so that a V of side slope 0.16 saturates at
/// about 0.76, and young, sharp land reads more strongly than old, rounded land.
Grid<float> curvature(const Heightfield& heights, int radius) {
  Grid<float> mean = smooth(heights, radius);
  const double scale = 0.08 * radius * heights.cell_size_m;
  for (std::size_t i = 0; i < mean.size(); ++i)
    mean.data()[i] = static_cast<float>(std::tanh((mean.data()[i] - heights.data()[i]) / scale));
  return mean;
}

int samples_for(double metres, double cell_m, int least) {
  return std::clamp(static_cast<int>(std::lround(metres / cell_m)), least, 64);
}

}  // namespace

std::vector<std::uint8_t> ground_map_texels(const Heightfield& heights, const GroundMapParams& params, const Grid<float>* wetness) {
  const int w = heights.width(), h = heights.height();
  assert(w >= 2 && h >= 2 && heights.cell_size_m > 0.0);
  const double cell = heights.cell_size_m;

  // Where water goes: D8 over the unfilled ground (pits stay wet).
  const water::Outlets outlets{params.sea_level_m};
  const Grid<water::CellIndex> receiver = water::d8_receivers(heights, outlets);
  const std::vector<water::CellIndex> stack = water::receiver_stack(receiver);
  const Grid<double> area = water::d8_drainage_area(receiver, stack, cell);
  // Wet from about 200 cells of 10 m (2 ha) upslope, fully at 60 ha: valley floors, not rills.
  const double wet_from = std::log10(std::max(2.0e4, 20.0 * cell * cell));
  Grid<float> wet(w, h, 0.0f);
  for (std::size_t i = 0; i < wet.size(); ++i)
    wet.data()[i] = static_cast<float>(std::clamp((std::log10(area.data()[i]) - wet_from) / 1.5, 0.0, 1.0));
  // Channels are a sample wide: widen them to their floors (about 30 m each side), then soften.
  const int floor_samples = samples_for(30.0, cell, 1);
  wet = smooth(dilate(wet, floor_samples), floor_samples);

  // Scree: debris leaves every steep cell down its D8 path, fading over the run-out.
  Grid<float> steep(w, h, 0.0f), debris(w, h, 0.0f);
  parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const double s = (slope_deg_at(heights, x, y) - params.cliff_slope_deg) / std::max(params.cliff_blend_deg, 1e-3) + 0.5;
      steep(x, y) = static_cast<float>(std::clamp(s, 0.0, 1.0));
    }
  });
  const double run_out_m = std::max(80.0, 2.0 * cell);
  const float fade = static_cast<float>(std::exp(-cell / run_out_m));
  float* d = debris.data();
  const float* st = steep.data();
  const water::CellIndex* rec = receiver.data();
  for (std::size_t k = stack.size(); k-- > 0;) {  // donors before their receivers
    const auto i = static_cast<std::size_t>(stack[k]);
    d[i] = std::max(d[i], st[i] > 0.5f ? st[i] : 0.0f);  // only true cliffs shed debris
    const auto r = static_cast<std::size_t>(rec[i]);
    if (r != i) d[r] = std::max(d[r], d[i] * fade);
  }
  // Debris rests below the cliff, on slopes a river does not clear (not on the wet valley floor).
  for (std::size_t i = 0; i < debris.size(); ++i) d[i] *= (1.0f - st[i]) * (1.0f - wet.data()[i]);
  debris = smooth(debris, samples_for(15.0, cell, 1));

  const Grid<float> fine = curvature(heights, samples_for(40.0, cell, 2));
  const Grid<float> broad = curvature(heights, samples_for(250.0, cell, 8));

  std::vector<std::uint8_t> texels(heights.size() * 4);
  parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      double wetter = wet(x, y);
      if (wetness != nullptr && !wetness->empty()) {
        const int gx = static_cast<int>(std::lround(double(x) * (wetness->width() - 1) / (w - 1)));
        const int gy = static_cast<int>(std::lround(double(y) * (wetness->height() - 1) / (h - 1)));
        wetter = std::max(wetter, static_cast<double>((*wetness)(gx, gy)));
      }
      std::uint8_t* texel = &texels[(static_cast<std::size_t>(y) * w + x) * 4];
      texel[0] = unit_byte(wetter);
      texel[1] = signed_byte(fine(x, y));
      texel[2] = unit_byte(1.6 * debris(x, y));
      texel[3] = signed_byte(broad(x, y));
    }
  });
  return texels;
}

DetailNoise detail_noise_texels(int size, double hurst, std::uint64_t seed) {
  assert(size >= 64 && (size & (size - 1)) == 0 && hurst > 0.0 && hurst <= 1.0);
  constexpr int octaves = 4;
  // Value noise with its derivative (per tile width): lattice indices wrap, so the tile repeats.
  struct Value {
    double v, du, dv;
  };
  auto value_noise = [&](std::uint64_t stream, int cells, double u, double v) {
    const double fx = u * cells, fy = v * cells;
    const int ix = static_cast<int>(std::floor(fx)), iy = static_cast<int>(std::floor(fy));
    const double tx = fx - ix, ty = fy - iy;
    const double sx = tx * tx * (3.0 - 2.0 * tx), sy = ty * ty * (3.0 - 2.0 * ty);
    const double dsx = 6.0 * tx * (1.0 - tx), dsy = 6.0 * ty * (1.0 - ty);
    auto lattice = [&](int i, int j) { return rng::uniform(seed, stream, ((i % cells) + cells) % cells, ((j % cells) + cells) % cells); };
    const double a = lattice(ix, iy), b = lattice(ix + 1, iy), c = lattice(ix, iy + 1), e = lattice(ix + 1, iy + 1);
    return Value{a + (b - a) * sx + (c - a) * sy + (a - b - c + e) * sx * sy, cells * dsx * ((b - a) + (a - b - c + e) * sy),
                 cells * dsy * ((c - a) + (a - b - c + e) * sx)};
  };
  const std::size_t n = static_cast<std::size_t>(size) * size;
  std::vector<double> height(n), du(n), dv(n), colour(n);
  double amplitude_sum = 0.0;
  for (int o = 0; o < octaves; ++o) amplitude_sum += std::pow(2.0, -o * hurst);
  parallel_for(0, size, [&](int y) {
    for (int x = 0; x < size; ++x) {
      const double u = (x + 0.5) / size, v = (y + 0.5) / size;
      double hs = 0.0, gu = 0.0, gv = 0.0, c = 0.0, camp = 0.5;
      for (int o = 0; o < octaves; ++o) {
        const double amplitude = std::pow(2.0, -o * hurst);
        const Value value = value_noise(static_cast<std::uint64_t>(o), 8 << o, u, v);
        hs += amplitude * (value.v - 0.5), gu += amplitude * value.du, gv += amplitude * value.dv;
        c += camp * value_noise(static_cast<std::uint64_t>(100 + o), 8 << o, u, v).v;
        camp *= 0.5;
      }
      const std::size_t i = static_cast<std::size_t>(y) * size + x;
      height[i] = hs / amplitude_sum, du[i] = gu, dv[i] = gv, colour[i] = c / 0.9375;
    }
  });
  double largest = 1e-9;
  for (std::size_t i = 0; i < n; ++i) largest = std::max({largest, std::abs(du[i]), std::abs(dv[i])});
  DetailNoise out;
  out.gradient_scale = largest;
  out.texels.resize(n * 4);
  for (std::size_t i = 0; i < n; ++i) {
    out.texels[4 * i] = signed_byte(du[i] / largest);
    out.texels[4 * i + 1] = signed_byte(dv[i] / largest);
    // Stretch the fbm's narrow spread (it clusters around the middle) over the byte range.
    out.texels[4 * i + 2] = unit_byte(0.5 + 1.8 * height[i]);
    out.texels[4 * i + 3] = unit_byte(0.5 + (colour[i] - 0.5) * 1.8);
  }
  return out;
}

}  // namespace sansui::look

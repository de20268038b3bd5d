#include "look/surface_layers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace sansui::look {
namespace {

/// 0 below edge - width/2, 1 above edge + width/2, linear between (the shader's ramp()).
double ramp(double edge, double width, double x) {
  return std::clamp((x - edge) / std::max(width, 1e-4) + 0.5, 0.0, 1.0);
}

struct Bands {
  double sea = 0.0, scale = 1.0;
  double tree_line = 0.5, snow_line = 0.75;  ///< fractions of `scale`
  const Land* land = nullptr;
};

Bands bands_of(const Heightfield& heights, const RenderParams& resolved, const std::optional<HeightSpan>& world = std::nullopt) {
  if (!lines_resolved(resolved.land)) fail("surface layers need a resolved look (tree and snow lines set)");
  Bands b;
  float highest = heights.values()[0];
  for (float h : heights.values()) highest = std::max(highest, h);
  if (world) {
    // A tile of a larger world: the world's highest and lowest, so that every tile bands alike.
    highest = world->highest;
    b.sea = resolved.sea ? resolved.sea_level_m : static_cast<double>(world->lowest) - 1.0;  // as effective_sea_level
  } else {
    b.sea = effective_sea_level(resolved, heights);
  }
  b.scale = band_scale_m(resolved.land, b.sea, highest);
  b.land = &resolved.land;
  b.tree_line = tree_line_fraction(resolved.land);
  b.snow_line = snow_line_fraction(resolved.land);
  return b;
}

/// Slope in degrees at sample (x, y), by central differences (one-sided at the border).
double slope_deg(const Heightfield& heights, int x, int y) {
  const int w = heights.width(), h = heights.height();
  const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, w - 1), y0 = std::max(y - 1, 0), y1 = std::min(y + 1, h - 1);
  const double dx = x1 > x0 ? (heights(x1, y) - heights(x0, y)) / ((x1 - x0) * heights.cell_size_m) : 0.0;
  const double dy = y1 > y0 ? (heights(x, y1) - heights(x, y0)) / ((y1 - y0) * heights.cell_size_m) : 0.0;
  return std::atan(std::sqrt(dx * dx + dy * dy)) * 180.0 / std::numbers::pi;
}

/// The layers at one sample as the shader blends them: each mix(a, b, t) moves weight t of
/// everything so far onto b, so the four weights always sum to 1.
struct Sample {
  double sand = 1.0, grass = 0.0, rock = 0.0, snow = 0.0;
  double forest_position = 0.0;  ///< 0 at the beach, 1 at the tree line
};

Sample layers_at(const Bands& b, double height_m, double slope) {
  const Land& land = *b.land;
  const double e = (height_m - b.sea) / b.scale;
  Sample s;
  s.forest_position = std::clamp((e - land.beach_top) / std::max(b.tree_line - land.beach_top, 1e-4), 0.0, 1.0);
  const auto mix_into = [&](double& layer, double t) {
    s.sand *= 1.0 - t, s.grass *= 1.0 - t, s.rock *= 1.0 - t, s.snow *= 1.0 - t;
    layer += t;
  };
  // Sand at beach height only, with its own narrow blend in metres (the shader's ground_albedo()).
  const double beach_m = land.beach_top * b.scale;
  mix_into(s.grass, ramp(beach_m, std::max(1.0, 0.6 * beach_m), height_m - b.sea));
  mix_into(s.rock, ramp(b.tree_line, land.blend, e));
  if (e >= 0.0) mix_into(s.rock, ramp(land.cliff_slope_deg, land.cliff_blend_deg, slope));
  mix_into(s.snow, ramp(b.snow_line, land.blend, e) * (1.0 - ramp(land.snow_max_slope_deg, 8.0, slope)));
  return s;
}

}  // namespace

SurfaceWeights surface_weights(const Heightfield& heights, const RenderParams& resolved, const std::optional<HeightSpan>& world) {
  if (heights.empty()) fail("surface layers of an empty heightfield");
  const Bands b = bands_of(heights, resolved, world);
  const int w = heights.width(), h = heights.height();
  SurfaceWeights out{Grid<float>(w, h, 0.0f), Grid<float>(w, h, 0.0f), Grid<float>(w, h, 0.0f), Grid<float>(w, h, 0.0f)};
  parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const Sample s = layers_at(b, heights(x, y), slope_deg(heights, x, y));
      out.sand(x, y) = static_cast<float>(s.sand);
      out.grass(x, y) = static_cast<float>(s.grass);
      out.rock(x, y) = static_cast<float>(s.rock);
      out.snow(x, y) = static_cast<float>(s.snow);
    }
  });
  return out;
}

Image splat_weights_image(const SurfaceWeights& weights) {
  const std::array<const Grid<float>*, 4> layers{&weights.sand, &weights.grass, &weights.rock, &weights.snow};
  Image image = Image::uninitialized(weights.sand.width(), weights.sand.height());
  parallel_for(0, image.height(), [&](int y) {
    for (int x = 0; x < image.width(); ++x) {
      std::array<int, 4> level{};
      std::array<double, 4> remainder{};
      int total = 0;
      for (std::size_t k = 0; k < 4; ++k) {
        const double scaled = std::clamp(static_cast<double>((*layers[k])(x, y)), 0.0, 1.0) * 255.0;
        level[k] = static_cast<int>(std::floor(scaled));
        remainder[k] = scaled - std::floor(scaled);
        total += level[k];
      }
      for (; total < 255; ++total) {
        const auto largest = static_cast<std::size_t>(std::ranges::max_element(remainder) - remainder.begin());
        ++level[largest];
        remainder[largest] = -1.0;
      }
      image(x, y) = Rgba8{static_cast<std::uint8_t>(level[0]), static_cast<std::uint8_t>(level[1]), static_cast<std::uint8_t>(level[2]),
                          static_cast<std::uint8_t>(level[3])};
    }
  });
  return image;
}

Image band_colour_map(const Heightfield& heights, const RenderParams& resolved, int max_side) {
  if (heights.empty()) fail("a colour map of an empty heightfield");
  if (max_side < 2) fail("colour map size {} is not allowed: it must be >= 2", max_side);
  const Bands b = bands_of(heights, resolved);
  const Land& land = resolved.land;
  const Rgb seabed = resolved.water.seabed.value_or(*land.beach);
  const int w = std::min(heights.width(), max_side), h = std::min(heights.height(), max_side);
  Image image = Image::uninitialized(w, h);
  const auto source = [](int i, int n, int samples) {
    return n > 1 ? static_cast<int>(std::lround(double(i) * (samples - 1) / (n - 1))) : 0;
  };
  parallel_for(0, h, [&](int py) {
    const int y = source(py, h, heights.height());
    for (int px = 0; px < w; ++px) {
      const int x = source(px, w, heights.width());
      const double height_m = heights(x, y);
      const Sample s = layers_at(b, height_m, slope_deg(heights, x, y));
      // The sand layer is the seabed under the sea, blending into the beach at the coast.
      const double coast = ramp(0.0, 0.25 * land.blend, (height_m - b.sea) / b.scale);
      const auto channel = [&](float Rgb::*c) {
        const double sand = (1.0 - coast) * seabed.*c + coast * (*land.beach).*c;
        const double forest = (1.0 - s.forest_position) * (*land.forest_low).*c + s.forest_position * (*land.forest_high).*c;
        const double value = s.sand * sand + s.grass * forest + s.rock * (*land.cliff).*c + s.snow * (*land.snow).*c;
        return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
      };
      image(px, py) = Rgba8{channel(&Rgb::r), channel(&Rgb::g), channel(&Rgb::b), 255};
    }
  });
  return image;
}

}  // namespace sansui::look

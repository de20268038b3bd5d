// Horizon sweeps over a heightfield for sun shadows and ambient occlusion (see the header for
// why these run on the CPU). Shadows follow the classic "shadow height" propagation: walking
// away from the sun one row at a time, the height of the shadow surface above a sample is the
// higher of the ground there and the shadow surface one step nearer the sun, lowered by the
// sun's drop over that step; the nearer row is interpolated linearly between its samples.
#include "look/horizon_shading.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/parallel.hpp"
#include "look/colour_space.hpp"

namespace sansui::look {
namespace {

Grid<float> transposed(const Grid<float>& grid) {
  auto out = Grid<float>::uninitialized(grid.height(), grid.width(), grid.cell_size_m);
  for (int y = 0; y < grid.height(); ++y)
    for (int x = 0; x < grid.width(); ++x) out(y, x) = grid(x, y);
  return out;
}

Grid<float> scaled(const Heightfield& heights, double scale) {
  Grid<float> out = heights;
  for (float& value : out.values()) value = static_cast<float>(value * scale);
  return out;
}

/// Adds the lit fraction (0..1) for one sun elevation to `lit_sum`. The sun's horizontal
/// direction per grid step is (toward_x, toward_y) with |toward_y| >= |toward_x|: rows are
/// walked from the sun's side, each sample looking one row back toward the sun.
void sweep_rows(const Grid<float>& heights, double toward_x, double toward_y, double tan_elevation, Grid<float>& lit_sum) {
  const int width = heights.width(), height = heights.height();
  const int toward_row = toward_y > 0.0 ? 1 : -1;
  const double shift = toward_x / std::abs(toward_y);  // x offset of the sample one row nearer the sun
  const double step_m = heights.cell_size_m * std::sqrt(1.0 + shift * shift);
  const float drop = static_cast<float>(step_m * tan_elevation);
  // The shadow edge fades over one step's drop (and at least a millimetre, for a low sun).
  const float fade = std::max(drop, 1e-3f);
  constexpr float none = -std::numeric_limits<float>::infinity();

  std::vector<float> nearer(width), current(width);
  const int first = toward_row > 0 ? height - 1 : 0;
  for (int x = 0; x < width; ++x) {
    nearer[x] = heights(x, first);
    lit_sum(x, first) += 1.0f;
  }
  for (int y = first - toward_row; y >= 0 && y < height; y -= toward_row) {
    const auto ground = heights.row(y);
    auto lit = lit_sum.row(y);
    for (int x = 0; x < width; ++x) {
      const double at = x + shift;
      float shadow = none;
      if (at >= 0.0 && at <= width - 1) {
        const int left = std::min(static_cast<int>(at), width - 2 < 0 ? 0 : width - 2);
        const float t = static_cast<float>(at - left);
        const float a = nearer[left], b = nearer[std::min(left + 1, width - 1)];
        shadow = (a + (b - a) * t) - drop;
      }
      if (shadow == none) {
        lit[x] += 1.0f;
        current[x] = ground[x];
      } else {
        lit[x] += std::clamp(0.5f + (ground[x] - shadow) / fade, 0.0f, 1.0f);
        current[x] = std::max(ground[x], shadow);
      }
    }
    std::swap(nearer, current);
  }
}

}  // namespace

Grid<float> sun_visibility(const Heightfield& heights, const SunShadowParams& params) {
  // The sun's horizontal direction in grid axes: x east, y south.
  const double azimuth = params.azimuth_deg * degrees;
  const double toward_x = std::sin(azimuth), toward_y = -std::cos(azimuth);
  // Rows must be the major axis of the sweep; otherwise sweep the transposed grid.
  const bool transpose = std::abs(toward_x) > std::abs(toward_y);
  Grid<float> ground = scaled(heights, params.vertical_scale);
  if (transpose) ground = transposed(ground);
  const double major = transpose ? toward_x : toward_y, minor = transpose ? toward_y : toward_x;

  // A few sun elevations across the penumbra, averaged: a soft shadow edge.
  constexpr int passes = 5;
  std::array<Grid<float>, passes> lit;
  parallel_for(0, passes, [&](int pass) {
    lit[pass] = Grid<float>(ground.width(), ground.height(), 0.0f, ground.cell_size_m);
    const double offset = params.penumbra_deg * (2.0 * pass / (passes - 1) - 1.0);
    const double elevation = std::clamp(params.elevation_deg + offset, 0.0, 90.0);
    const double tan_elevation = elevation >= 90.0 ? 1e9 : std::tan(elevation * degrees);
    sweep_rows(ground, minor, major, tan_elevation, lit[pass]);
  });
  Grid<float> result = std::move(lit[0]);
  for (int pass = 1; pass < passes; ++pass)
    for (std::size_t i = 0; i < result.size(); ++i) result.data()[i] += lit[pass].data()[i];
  for (float& value : result.values()) value /= passes;
  if (transpose) result = transposed(result);
  result.copy_metadata_from(heights);
  return result;
}

Grid<float> ambient_occlusion(const Heightfield& heights, const AmbientOcclusionParams& params) {
  const Grid<float> ground = scaled(heights, params.vertical_scale);
  const int width = ground.width(), height = ground.height();
  constexpr std::array<std::array<int, 2>, 8> directions{{{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};
  // Roughly geometric distances: near steps catch small hollows, far ones whole valleys.
  std::vector<int> distances;
  for (int d : {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256})
    if (d <= params.radius_samples) distances.push_back(d);

  auto result = Grid<float>::uninitialized(width, height, heights.cell_size_m);
  result.copy_metadata_from(heights);
  // Row by row, and within a row one direction and distance at a time, so that the inner
  // loop reads two rows front to back (the rows within the radius stay in cache).
  parallel_for(0, height, [&](int y) {
    const auto here = ground.row(y);
    std::vector<float> best(width), occlusion(width, 0.0f);
    for (const auto& [dx, dy] : directions) {
      const double step_m = ground.cell_size_m * ((dx != 0 && dy != 0) ? std::numbers::sqrt2 : 1.0);
      std::fill(best.begin(), best.end(), 0.0f);  // largest horizon tangent so far (0: flat)
      for (int d : distances) {
        const int other_y = y + dy * d, shift = dx * d;
        if (other_y < 0 || other_y >= height || std::abs(shift) >= width) break;
        const float* other = ground.row(other_y).data() + shift;
        const int x0 = std::max(0, -shift), x1 = std::min(width, width - shift);
        const auto inverse = static_cast<float>(1.0 / (step_m * d));
        for (int x = x0; x < x1; ++x) best[x] = std::max(best[x], (other[x] - here[x]) * inverse);
      }
      for (int x = 0; x < width; ++x) occlusion[x] += best[x] * best[x] / (1.0f + best[x] * best[x]);  // sin^2
    }
    auto out = result.row(y);
    for (int x = 0; x < width; ++x) out[x] = 1.0f - occlusion[x] / static_cast<float>(directions.size());
  });
  return result;
}

}  // namespace sansui::look

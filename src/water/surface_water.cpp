#include "water/surface_water.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/parallel.hpp"

namespace sansui::water {
namespace {

constexpr double seconds_per_year = 365.25 * 24.0 * 3600.0;

/// The values at fractions low <= high of the sorted values (nearest rank), reordering them: the
/// second search looks only above the first's rank.
std::pair<double, double> quantiles(std::vector<float>& values, double low, double high) {
  if (values.empty()) return {0.0, 0.0};
  const auto rank = [&](double q) { return static_cast<std::ptrdiff_t>(std::clamp(q, 0.0, 1.0) * static_cast<double>(values.size() - 1)); };
  const std::ptrdiff_t k_low = rank(low), k_high = std::max(rank(high), k_low);
  std::nth_element(values.begin(), values.begin() + k_low, values.end());
  const double at_low = values[static_cast<std::size_t>(k_low)];  // before the second search moves it
  std::nth_element(values.begin() + k_low, values.begin() + k_high, values.end());
  return {at_low, values[static_cast<std::size_t>(k_high)]};
}

/// Topographic wetness index per cell on the filled surface: ln(a / tan b), a the specific
/// catchment area (drainage area per unit contour width, the cell side), b the local slope.
Grid<float> wetness_index(const Heightfield& surface, const Grid<double>& area_m2) {
  const int w = surface.width(), h = surface.height();
  const double cell = surface.cell_size_m;
  Grid<float> index(w, h, 0.0f);
  copy_placement(index, surface);
  parallel_for(0, h, [&](int y) {  // each cell on its own: the same bytes with any number of threads
    for (int x = 0; x < w; ++x) {
      const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, w - 1), y0 = std::max(y - 1, 0), y1 = std::min(y + 1, h - 1);
      const double dx = (surface(x1, y) - surface(x0, y)) / (std::max(x1 - x0, 1) * cell);
      const double dy = (surface(x, y1) - surface(x, y0)) / (std::max(y1 - y0, 1) * cell);
      const double slope = std::max(std::hypot(dx, dy), 1e-4);  // flats: very wet, not infinite
      index(x, y) = static_cast<float>(std::log(area_m2(x, y) / cell / slope));
    }
  });
  return index;
}

/// Pits of a few cells (droplet erosion leaves thousands) are puddles, not lakes: they are
/// taken out of the list, their cells dry again (the water still routes through them).
void drop_small_lakes(LakeFill& fill, const Heightfield& ground) {
  std::vector<std::int32_t> renumber(fill.lakes.size() + 1, 0);
  std::vector<Lake> kept;
  for (std::size_t k = 0; k < fill.lakes.size(); ++k)
    if (fill.lakes[k].cells >= min_lake_cells) {
      kept.push_back(fill.lakes[k]);
      renumber[k + 1] = static_cast<std::int32_t>(kept.size());
    }
  for (std::size_t i = 0; i < fill.lake.size(); ++i) {
    std::int32_t& label = fill.lake.values()[i];
    if (label == 0) continue;
    label = renumber[static_cast<std::size_t>(label)];
    if (label == 0) fill.surface.values()[i] = ground.values()[i];
  }
  fill.lakes = std::move(kept);
}

}  // namespace

double river_width_m(double discharge_m3_per_s) {
  return 2.7 * std::sqrt(std::max(discharge_m3_per_s, 0.0));
}

double river_depth_m(double discharge_m3_per_s) {
  return 0.3 * std::pow(std::max(discharge_m3_per_s, 0.0), 0.4);
}

SurfaceWater surface_water(const Heightfield& heights, const FlowParams& params, const Context& context,
                           const FlowRouting* routing_of_heights) {
  params.validate();
  SurfaceWater water;
  // Over the ground, not the lake surface: the routing crosses lakes from inflow to outflow
  // itself, and its surface is the lakes' level.
  FlowRouting own;
  if (routing_of_heights == nullptr) own = route_flow(heights, params.outlets(), context);
  const FlowRouting& flow = routing_of_heights != nullptr ? *routing_of_heights : own;
  water.lakes = lakes_of(heights, flow.surface);
  drop_small_lakes(water.lakes, heights);
  water.surface = water.lakes.surface;
  context.check_cancelled();
  water.rivers = extract_rivers(flow, params);
  if (routing_of_heights != nullptr)
    water.area_m2 = flow.area_m2;
  else
    water.area_m2 = std::move(own.area_m2);

  const int w = heights.width(), h = heights.height();
  const double cell = heights.cell_size_m;
  water.depth_m = Grid<float>(w, h, 0.0f);
  copy_placement(water.depth_m, heights);
  const auto sea = static_cast<float>(params.sea_level_m.value_or(-1e30));
  parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x)
      if (water.lakes.lake(x, y) != 0 && heights(x, y) >= sea) water.depth_m(x, y) = water.lakes.surface(x, y) - heights(x, y);
  });

  // Rivers: each channel cell paints a disc as wide as the river there (at least its own cell),
  // as deep as the discharge makes it; the deepest wins where discs overlap.
  const double runoff_m_per_s = params.runoff_mm_per_yr / 1000.0 / seconds_per_year;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (water.rivers.channel(x, y) == 0 || heights(x, y) < sea) continue;
      const double discharge = water.area_m2(x, y) * runoff_m_per_s;
      const auto depth = static_cast<float>(river_depth_m(discharge));
      const double radius = 0.5 * river_width_m(discharge) / cell;
      const int reach = static_cast<int>(std::floor(radius));
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx) {
          const int px = x + dx, py = y + dy;
          if (px < 0 || py < 0 || px >= w || py >= h || dx * dx + dy * dy > radius * radius + 0.25) continue;
          water.depth_m(px, py) = std::max(water.depth_m(px, py), depth);
        }
    }
  context.check_cancelled();

  // Wetness: the index between its 70th (dry) and 99th (wet) percentiles over land, 1 in water.
  const Grid<float> index = wetness_index(water.surface, water.area_m2);
  std::vector<float> land;
  land.reserve(index.size());
  for (std::size_t i = 0; i < index.size(); ++i)
    if (heights.values()[i] >= sea) land.push_back(index.values()[i]);
  // Not a structured binding: the lambda below captures them (clang before 16 cannot).
  const std::pair<double, double> percentiles = quantiles(land, 0.70, 0.99);
  const double dry = percentiles.first, wet = percentiles.second;
  water.wetness = Grid<float>(w, h, 0.0f);
  copy_placement(water.wetness, heights);
  parallel_for_ranges<std::size_t>(0, index.size(), 1 << 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const double scaled = (index.values()[i] - dry) / std::max(wet - dry, 1e-6);
      water.wetness.values()[i] = water.depth_m.values()[i] > 0.0f ? 1.0f : static_cast<float>(std::clamp(scaled, 0.0, 1.0));
    }
  });
  return water;
}

}  // namespace sansui::water

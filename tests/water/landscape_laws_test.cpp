// Physical checks on an eroded fractal terrain: the laws measured on real drainage basins.
// Ranges from the landscape-evolution literature (Flint 1974; Hack 1957; Rodriguez-Iturbe &
// Rinaldo, "Fractal River Basins", 1997, for the area exceedance exponent).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include <gtest/gtest.h>

#include "water/flow.hpp"
#include "water/stream_power.hpp"
#include "water/water_test_util.hpp"

namespace sansui::water {
namespace {

/// Least-squares slope of log y against log x.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const auto n = static_cast<double>(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

struct Laws {
  double flint_theta, hack_h, exceedance_tau, channel_slope, hillslope_slope;
};

Laws measure(const Heightfield& h, double channel_area_m2) {
  const FlowRouting flow = route_flow(h, {});
  const int width = h.width();
  const std::size_t n = h.size();
  std::vector<double> slope(n, 0.0), length(n, 0.0);
  for (std::size_t k = n; k-- > 0;) {  // upstream first: the longest flow path to each cell
    const CellIndex i = flow.stack[k], r = flow.receiver.data()[i];
    if (r == i) continue;
    const double step = h.cell_size_m * ((r % width != i % width && r / width != i / width) ? std::sqrt(2.0) : 1.0);
    slope[static_cast<std::size_t>(i)] = (static_cast<double>(h.data()[i]) - h.data()[r]) / step;
    length[static_cast<std::size_t>(r)] = std::max(length[static_cast<std::size_t>(r)], length[static_cast<std::size_t>(i)] + step);
  }
  std::vector<double> area, channel_slopes, hill_slopes, lengths, length_areas;
  for (std::size_t i = 0; i < n; ++i) {
    if (flow.receiver.data()[i] == static_cast<CellIndex>(i)) continue;
    const double a = flow.area_m2.data()[i];
    if (a >= channel_area_m2) {
      if (slope[i] > 0) area.push_back(a), channel_slopes.push_back(slope[i]);
      lengths.push_back(length[i]), length_areas.push_back(a);
    } else {
      hill_slopes.push_back(slope[i]);
    }
  }
  Laws laws{};
  laws.flint_theta = -log_log_slope(area, channel_slopes);
  laws.hack_h = log_log_slope(length_areas, lengths);
  // P(A >= a) at areas from 10 cells to a hundredth of the map, spaced evenly in log a.
  std::vector<double> all_areas(flow.area_m2.values().begin(), flow.area_m2.values().end());
  std::sort(all_areas.begin(), all_areas.end());
  const double cell = h.cell_size_m * h.cell_size_m;
  std::vector<double> a_values, exceedance;
  for (double a = 10 * cell; a <= 0.01 * static_cast<double>(n) * cell; a *= 1.25) {
    const auto above = all_areas.end() - std::lower_bound(all_areas.begin(), all_areas.end(), a);
    a_values.push_back(a), exceedance.push_back(static_cast<double>(above) / static_cast<double>(n));
  }
  laws.exceedance_tau = -log_log_slope(a_values, exceedance);
  laws.channel_slope = median(channel_slopes);
  laws.hillslope_slope = median(hill_slopes);
  return laws;
}

TEST(LandscapeLaws, ErodedFractalTerrainDrainsLikeRealLand) {
  const Heightfield start = test::midpoint_terrain(257, 30.0, 21, 300.0);
  StreamPowerParams p;
  p.erodibility = 2e-5;
  p.uplift_m_per_yr = 5e-4;
  // Diffusion off: the laws are those of the fluvial network. With D = 0.002 m^2/yr at 30 m cells the
  // valley floors smooth out, D8 channels wander on them and Flint's theta drops to about 0.13
  // (measured; see the water library's notes), so the check is on the stream-power stage alone.
  p.diffusivity_m2_per_yr = 0.0;
  p.deposition = 0.0;
  p.steps = 40;
  p = params_for_stage(start, p, ErosionStage::peneplain);  // 8 tau: close to steady state
  const ErosionResult eroded = erode_stream_power(start, p);
  const double channel_area = 100 * 900.0;
  const Laws laws = measure(eroded.heights, channel_area);
  const Laws before = measure(start, channel_area);
  std::cout << "eroded: Flint theta " << laws.flint_theta << ", Hack h " << laws.hack_h << ", exceedance tau " << laws.exceedance_tau
            << ", median slope channels " << laws.channel_slope << " hillslopes " << laws.hillslope_slope << "\n"
            << "uneroded: Flint theta " << before.flint_theta << ", Hack h " << before.hack_h << ", exceedance tau "
            << before.exceedance_tau << ", median slope channels " << before.channel_slope << " hillslopes " << before.hillslope_slope
            << "\n";
  EXPECT_GE(laws.flint_theta, 0.35);
  EXPECT_LE(laws.flint_theta, 0.6);
  EXPECT_GE(laws.hack_h, 0.5);
  EXPECT_LE(laws.hack_h, 0.65);
  EXPECT_GE(laws.exceedance_tau, 0.38);
  EXPECT_LE(laws.exceedance_tau, 0.5);
  EXPECT_LE(laws.channel_slope, 0.5 * laws.hillslope_slope);
}

}  // namespace
}  // namespace sansui::water

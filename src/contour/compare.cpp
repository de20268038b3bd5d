// DEM measures and comparison (SPEC 1.4): see compare.hpp.
#include "contour/compare.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>

#include <fmt/format.h>
#include <unsupported/Eigen/FFT>

#include "contour/extract.hpp"
#include "contour/fourier.hpp"
#include "contour/grid_frame.hpp"
#include "core/error.hpp"
#include "core/line_fit.hpp"

namespace sansui::contour {
namespace {

/// The cells that count, as a grid of 0/1 (the ring test once per cell).
Grid<std::uint8_t> mask_of(const Heightfield& dem, const CellMask& mask) {
  Grid<std::uint8_t> out(dem.width(), dem.height(), 0);
  const GridFrame frame = GridFrame::of(dem);
  for (int j = 0; j < dem.height(); ++j)
    for (int i = 0; i < dem.width(); ++i) {
      const float z = dem(i, j);
      out(i, j) =
          std::isfinite(z) && (!mask.above_m || z >= *mask.above_m) && (mask.inside == nullptr || contains(*mask.inside, frame.at(i, j)))
              ? 1
              : 0;
    }
  return out;
}

/// Least-squares slope of y against x.
double fit_slope(const std::vector<double>& x, const std::vector<double>& y) {
  return fit_line(x, y).slope;
}

void measure_hypsometry(const Heightfield& dem, const Grid<std::uint8_t>& counted, DemMeasures& m) {
  std::vector<std::size_t> bins(101, 0);
  const double span = m.max_m - m.min_m;
  for (std::size_t k = 0; k < dem.size(); ++k) {
    if (counted.data()[k] == 0) continue;
    const double z = dem.data()[k];
    const double h = span > 0.0 ? (z - m.min_m) / span : 0.0;
    ++bins[static_cast<std::size_t>(std::clamp(static_cast<int>(std::floor(h * 100.0)), 0, 100))];
  }
  // a(h_i): fraction of cells whose relative height is at least h_i = i / 100.
  m.hypsometry.assign(101, 0.0);
  std::size_t at_or_above = 0;
  for (int i = 100; i >= 0; --i) {
    at_or_above += bins[static_cast<std::size_t>(i)];
    m.hypsometry[static_cast<std::size_t>(i)] = static_cast<double>(at_or_above) / static_cast<double>(m.cells);
  }
  m.hypsometric_integral = 0.0;
  for (int i = 0; i < 100; ++i)
    m.hypsometric_integral += 0.005 * (m.hypsometry[static_cast<std::size_t>(i)] + m.hypsometry[static_cast<std::size_t>(i) + 1]);
}

void measure_slopes(const Heightfield& dem, const Grid<std::uint8_t>& counted, DemMeasures& m) {
  m.slope_histogram.assign(90, 0.0);
  double total = 0.0, sum = 0.0;
  const double cell = dem.cell_size_m;
  std::vector<double> gradients;
  for (int j = 1; j + 1 < dem.height(); ++j)
    for (int i = 1; i + 1 < dem.width(); ++i) {
      if (counted(i, j) == 0) continue;
      const double gx = (dem(i + 1, j) - dem(i - 1, j)) / (2.0 * cell), gy = (dem(i, j + 1) - dem(i, j - 1)) / (2.0 * cell);
      const double gradient = std::sqrt(gx * gx + gy * gy);
      const double angle = std::atan(gradient) * 180.0 / std::numbers::pi;
      gradients.push_back(gradient);
      m.slope_histogram[static_cast<std::size_t>(std::clamp(static_cast<int>(angle), 0, 89))] += 1.0;
      sum += angle;
      total += 1.0;
    }
  if (total > 0.0)
    for (double& b : m.slope_histogram) b /= total;
  m.mean_slope_deg = total > 0.0 ? sum / total : 0.0;
  if (!gradients.empty()) {
    // Percentiles by selection: the 50th, then the 90th among the upper part.
    const auto at = [&](std::size_t k) {
      std::nth_element(gradients.begin(), gradients.begin() + static_cast<std::ptrdiff_t>(k), gradients.end());
      return gradients[k];
    };
    m.gradient_p50 = at(gradients.size() / 2);
    m.gradient_p90 = at(gradients.size() * 9 / 10);
  }
}

/// Peaks with prominence >= threshold: cells from the highest down, joined to their processed
/// 8-neighbours; where two peaks' regions meet, the lower peak's prominence is its height above
/// that saddle.
int count_summits(const Heightfield& dem, const Grid<std::uint8_t>& counted, double threshold) {
  const int w = dem.width(), h = dem.height();
  std::vector<std::int32_t> order;
  for (int k = 0; k < w * h; ++k)
    if (counted.data()[k] != 0) order.push_back(k);
  std::stable_sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) { return dem.data()[a] > dem.data()[b]; });
  std::vector<std::int32_t> parent(static_cast<std::size_t>(w) * h, -1), peak(static_cast<std::size_t>(w) * h, -1);
  auto find = [&](std::int32_t x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
      parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
      x = parent[static_cast<std::size_t>(x)];
    }
    return x;
  };
  int summits = 0;
  float lowest = order.empty() ? 0.0f : dem.data()[order.back()];
  for (std::int32_t k : order) {
    parent[static_cast<std::size_t>(k)] = k;
    peak[static_cast<std::size_t>(k)] = k;
    const int x = k % w, y = k / w;
    const float z = dem.data()[k];
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        const std::int32_t n = ny * w + nx;
        if (parent[static_cast<std::size_t>(n)] < 0) continue;
        const std::int32_t a = find(k), b = find(n);
        if (a == b) continue;
        const std::int32_t pa = peak[static_cast<std::size_t>(a)], pb = peak[static_cast<std::size_t>(b)];
        const bool a_higher = dem.data()[pa] > dem.data()[pb] || (dem.data()[pa] == dem.data()[pb] && pa < pb);
        const std::int32_t lower = a_higher ? pb : pa;
        if (lower != k && dem.data()[lower] - z >= threshold) ++summits;  // the lower peak ends here
        parent[static_cast<std::size_t>(a_higher ? b : a)] = a_higher ? a : b;
        peak[static_cast<std::size_t>(a_higher ? a : b)] = a_higher ? pa : pb;
      }
  }
  // Peaks never merged into a higher one: each region's highest, measured from the lowest cell.
  for (std::int32_t k : order)
    if (find(k) == k && dem.data()[peak[static_cast<std::size_t>(k)]] - lowest >= threshold) ++summits;
  return summits;
}

/// Total contour length at `level`, without the pieces that run along the grid's border.
double contour_length(const std::vector<Ring>& rings, const GridFrame& frame, int w, int h) {
  double total = 0.0;
  auto inside = [&](Point p) {
    const double c = frame.column(p.x), r = frame.row(p.y);
    return c >= -1e-9 && r >= -1e-9 && c <= w - 1 + 1e-9 && r <= h - 1 + 1e-9;
  };
  for (const Ring& ring : rings)
    for (std::size_t i = 0, n = ring.size(); i < n; ++i)
      if (inside(ring[i]) && inside(ring[(i + 1) % n])) total += distance(ring[i], ring[(i + 1) % n]);
  return total;
}

/// Mean normalised power of the P-type descriptors of the contour lines, fitted in log-log.
double contour_spectrum_slope(const std::vector<std::vector<Ring>>& levels, double cell) {
  constexpr int n = 256, k_max = 32;
  std::vector<double> power(k_max + 1, 0.0);
  double weight = 0.0;
  for (const auto& rings : levels)
    for (const Ring& ring : rings) {
      const double length = perimeter(ring);
      if (length < 32.0 * cell) continue;
      const Ring z = resample_closed(ring, n);
      Steps w;
      const double h = length / n;
      for (std::size_t j = 0; j < z.size(); ++j) {
        const Point d = z[(j + 1) % z.size()] - z[j];
        w.emplace_back(d.x / h, d.y / h);
      }
      const Steps c = descriptors_of_steps(w);
      double total = 0.0;
      for (const auto& v : c) total += std::norm(v);
      if (!(total > 0.0)) continue;
      for (int k = 1; k <= k_max; ++k)
        power[static_cast<std::size_t>(k)] +=
            length * 0.5 * (std::norm(c[static_cast<std::size_t>(k)]) + std::norm(c[static_cast<std::size_t>(n - k)])) / total;
      weight += length;
    }
  if (weight <= 0.0) return 0.0;
  std::vector<double> x, y;
  for (int k = 2; k <= k_max; ++k)
    if (power[static_cast<std::size_t>(k)] > 0.0) {
      x.push_back(std::log10(k));
      y.push_back(std::log10(power[static_cast<std::size_t>(k)] / weight));
    }
  return fit_slope(x, y);
}

/// Radially averaged power spectrum of the centre square (a power of two, at most 1024) of the
/// DEM, Hann-windowed, fitted in log-log between 2 cycles and a quarter of Nyquist.
double dem_spectrum_slope(const Heightfield& dem, const CellMask& mask) {
  int s = 1;
  while (2 * s <= std::min({dem.width(), dem.height(), 1024})) s *= 2;
  if (s < 16) return 0.0;
  const int x0 = (dem.width() - s) / 2, y0 = (dem.height() - s) / 2;
  double mean = 0.0;
  auto value = [&](int i, int j) {
    const float z = dem(x0 + i, y0 + j);
    return mask.above_m && z < *mask.above_m ? *mask.above_m : static_cast<double>(z);
  };
  for (int j = 0; j < s; ++j)
    for (int i = 0; i < s; ++i) mean += value(i, j);
  mean /= static_cast<double>(s) * s;
  std::vector<std::vector<std::complex<double>>> rows(static_cast<std::size_t>(s));
  Eigen::FFT<double> fft;
  std::vector<double> window(static_cast<std::size_t>(s));
  for (int i = 0; i < s; ++i) window[static_cast<std::size_t>(i)] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * i / s);
  for (int j = 0; j < s; ++j) {
    std::vector<std::complex<double>> in(static_cast<std::size_t>(s));
    for (int i = 0; i < s; ++i)
      in[static_cast<std::size_t>(i)] = (value(i, j) - mean) * window[static_cast<std::size_t>(i)] * window[static_cast<std::size_t>(j)];
    fft.fwd(rows[static_cast<std::size_t>(j)], in);
  }
  std::vector<double> power(static_cast<std::size_t>(s), 0.0), count(static_cast<std::size_t>(s), 0.0);
  std::vector<std::complex<double>> column(static_cast<std::size_t>(s)), spectrum;
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j < s; ++j) column[static_cast<std::size_t>(j)] = rows[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)];
    fft.fwd(spectrum, column);
    const int kx = i <= s / 2 ? i : s - i;
    for (int j = 0; j < s; ++j) {
      const int ky = j <= s / 2 ? j : s - j;
      const auto r = static_cast<std::size_t>(std::lround(std::sqrt(static_cast<double>(kx * kx + ky * ky))));
      if (r < power.size()) power[r] += std::norm(spectrum[static_cast<std::size_t>(j)]), count[r] += 1.0;
    }
  }
  std::vector<double> x, y;
  for (int r = 2; r <= s / 8; ++r)
    if (count[static_cast<std::size_t>(r)] > 0.0 && power[static_cast<std::size_t>(r)] > 0.0) {
      x.push_back(std::log10(r));
      y.push_back(std::log10(power[static_cast<std::size_t>(r)] / count[static_cast<std::size_t>(r)]));
    }
  return fit_slope(x, y);
}

void range_of(const Heightfield& dem, const Grid<std::uint8_t>& counted, DemMeasures& m) {
  m.min_m = INFINITY;
  m.max_m = -INFINITY;
  m.cells = 0;
  for (std::size_t k = 0; k < dem.size(); ++k)
    if (counted.data()[k] != 0) {
      const double z = dem.data()[k];
      m.min_m = std::min(m.min_m, z), m.max_m = std::max(m.max_m, z), ++m.cells;
    }
}

}  // namespace

DemMeasures measure_dem(const Heightfield& dem, const CellMask& mask, const std::vector<double>& levels, double prominence) {
  DemMeasures m;
  const Grid<std::uint8_t> counted = mask_of(dem, mask);
  range_of(dem, counted, m);
  if (m.cells == 0)
    fail("no cell of the DEM is counted (above {} m{})", mask.above_m.value_or(-INFINITY), mask.inside ? ", inside the ring" : "");
  measure_hypsometry(dem, counted, m);
  measure_slopes(dem, counted, m);
  m.summits = count_summits(dem, counted, prominence);
  const GridFrame frame = GridFrame::of(dem);
  std::vector<std::vector<Ring>> rings;
  for (double level : levels) {
    rings.push_back(extract_contours(dem, level));
    m.levels_m.push_back(level);
    m.contour_length_m.push_back(contour_length(rings.back(), frame, dem.width(), dem.height()));
  }
  m.contour_spectrum_slope = contour_spectrum_slope(rings, dem.cell_size_m);
  m.dem_spectrum_slope = dem_spectrum_slope(dem, mask);
  return m;
}

Comparison compare_dems(const Heightfield& real, const Heightfield& generated, const CompareParams& params, const Context& context) {
  if (params.above_m && !std::isfinite(*params.above_m)) fail("--above {} is not allowed: give a finite elevation", *params.above_m);
  if (params.interval_m && !(*params.interval_m > 0.0)) fail("--interval {} is not allowed: it must be > 0", *params.interval_m);
  if (params.prominence_m && !(*params.prominence_m > 0.0)) fail("--prominence {} is not allowed: it must be > 0", *params.prominence_m);
  DemMeasures r, g;
  const CellMask mask{params.above_m, params.inside ? &*params.inside : nullptr};
  range_of(real, mask_of(real, mask), r);
  range_of(generated, mask_of(generated, mask), g);
  if (r.cells == 0 || g.cells == 0)
    fail("no cell of the {} DEM is counted (at or above {} m{})", r.cells == 0 ? "real" : "generated", params.above_m.value_or(-INFINITY),
         params.inside ? ", inside the ring" : "");
  const double low = std::max(r.min_m, g.min_m), high = std::min(r.max_m, g.max_m);
  if (!(high > low))
    fail("the two DEMs share no elevation range ({:.1f}..{:.1f} m vs {:.1f}..{:.1f} m)", r.min_m, r.max_m, g.min_m, g.max_m);
  Comparison c;
  c.params = params;
  c.params.interval_m = params.interval_m.value_or((high - low) / 20.0);
  c.params.prominence_m = params.prominence_m.value_or(*c.params.interval_m);
  // Levels on multiples of the interval, as on a map, strictly inside the common range.
  const double step = *c.params.interval_m;
  std::vector<double> levels;
  for (double z = std::floor(low / step + 1.0) * step; z < high && levels.size() < 1000; z += step) levels.push_back(z);
  context.report("compare", 0.0);
  c.real = measure_dem(real, mask, levels, *c.params.prominence_m);
  context.report("compare", 0.5);
  c.generated = measure_dem(generated, mask, levels, *c.params.prominence_m);
  context.report("compare", 1.0);
  for (std::size_t i = 0; i <= 100; ++i) c.hypsometric_difference += std::fabs(c.real.hypsometry[i] - c.generated.hypsometry[i]) / 101.0;
  double cumulative = 0.0;
  for (std::size_t i = 0; i < 90; ++i) {
    cumulative += c.real.slope_histogram[i] - c.generated.slope_histogram[i];
    c.slope_distance_deg += std::fabs(cumulative);
  }
  int counted_levels = 0;
  for (std::size_t i = 0; i < levels.size(); ++i)
    if (c.real.contour_length_m[i] > 0.0) c.length_ratio += c.generated.contour_length_m[i] / c.real.contour_length_m[i], ++counted_levels;
  c.length_ratio = counted_levels > 0 ? c.length_ratio / counted_levels : 0.0;
  return c;
}

std::string comparison_table(const Comparison& c) {
  std::string out;
  auto row = [&](const std::string& metric, const std::string& real, const std::string& generated, const std::string& difference) {
    fmt::format_to(std::back_inserter(out), "{:<44} {:>12} {:>12} {:>12}\n", metric, real, generated, difference);
  };
  auto num = [](double v, int digits) { return fmt::format("{:.{}f}", v, digits); };
  row("metric", "real", "generated", "difference");
  row("cells compared", fmt::format("{}", c.real.cells), fmt::format("{}", c.generated.cells), "");
  row("elevation range (m)", fmt::format("{:.0f}..{:.0f}", c.real.min_m, c.real.max_m),
      fmt::format("{:.0f}..{:.0f}", c.generated.min_m, c.generated.max_m), "");
  row("hypsometric integral", num(c.real.hypsometric_integral, 3), num(c.generated.hypsometric_integral, 3),
      num(c.generated.hypsometric_integral - c.real.hypsometric_integral, 3));
  row("hypsometric curve difference (mean |da|)", "", "", num(c.hypsometric_difference, 3));
  row("mean slope (deg)", num(c.real.mean_slope_deg, 1), num(c.generated.mean_slope_deg, 1),
      num(c.generated.mean_slope_deg - c.real.mean_slope_deg, 1));
  row("slope histogram distance (EMD, deg)", "", "", num(c.slope_distance_deg, 2));
  row("slope spread (p90 / p50 of the gradient)", num(c.real.slope_spread(), 2), num(c.generated.slope_spread(), 2),
      num(c.generated.slope_spread() - c.real.slope_spread(), 2));
  row(fmt::format("summits (prominence >= {:g} m)", *c.params.prominence_m), fmt::format("{}", c.real.summits),
      fmt::format("{}", c.generated.summits), fmt::format("{:+d}", c.generated.summits - c.real.summits));
  row(fmt::format("contour length per level, gen/real ({} levels)", c.real.levels_m.size()), "", "", num(c.length_ratio, 3));
  row("contour power spectrum slope", num(c.real.contour_spectrum_slope, 2), num(c.generated.contour_spectrum_slope, 2),
      num(c.generated.contour_spectrum_slope - c.real.contour_spectrum_slope, 2));
  row("DEM power spectrum slope", num(c.real.dem_spectrum_slope, 2), num(c.generated.dem_spectrum_slope, 2),
      num(c.generated.dem_spectrum_slope - c.real.dem_spectrum_slope, 2));
  return out;
}

}  // namespace sansui::contour

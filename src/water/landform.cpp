// Landform measures (see landform.hpp).
#include "water/landform.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <unsupported/Eigen/FFT>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "water/flow.hpp"

namespace sansui::water {
namespace {

double median_of(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

/// Least-squares slope of y against x.
double fitted_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const auto n = static_cast<double>(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  const double denominator = n * sxx - sx * sx;
  return denominator > 0 ? (n * sxy - sx * sy) / denominator : 0.0;
}

/// Gradient magnitude at an interior sample, by central differences. [Units: m/m]
double gradient_at(const Heightfield& h, int x, int y) {
  const double dx = (static_cast<double>(h(x + 1, y)) - h(x - 1, y)) / (2.0 * h.cell_size_m);
  const double dy = (static_cast<double>(h(x, y + 1)) - h(x, y - 1)) / (2.0 * h.cell_size_m);
  return std::hypot(dx, dy);
}

/// `square` minus its least-squares plane, times a radial Hann window (Perron et al. 2008): no
/// edge of the square leaks into the spectrum.
std::vector<std::complex<double>> detrended_windowed(const std::vector<double>& square, int n) {
  double mean = 0, sx = 0, sy = 0;
  const double centre = 0.5 * (n - 1);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) mean += square[static_cast<std::size_t>(y) * n + x];
  mean /= static_cast<double>(n) * n;
  double sxx = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double v = square[static_cast<std::size_t>(y) * n + x] - mean;
      sx += (x - centre) * v, sy += (y - centre) * v;
    }
  for (int x = 0; x < n; ++x) sxx += (x - centre) * (x - centre);
  sxx *= n;  // the same sum over every row
  const double ax = sx / sxx, ay = sy / sxx;
  std::vector<std::complex<double>> out(square.size());
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const double rx = (x - centre) / centre, ry = (y - centre) / centre, r = std::hypot(rx, ry);
      const double window = r < 1.0 ? 0.5 * (1.0 + std::cos(std::numbers::pi * r)) : 0.0;
      const double v = square[static_cast<std::size_t>(y) * n + x] - mean - ax * (x - centre) - ay * (y - centre);
      out[static_cast<std::size_t>(y) * n + x] = v * window;
    }
  return out;
}

}  // namespace

void fft_2d(std::vector<std::complex<double>>& data, int n, bool inverse) {
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> line(static_cast<std::size_t>(n)), transformed;
  const auto transform = [&] { inverse ? fft.inv(transformed, line) : fft.fwd(transformed, line); };
  for (int y = 0; y < n; ++y) {
    std::copy_n(data.begin() + static_cast<std::ptrdiff_t>(y) * n, n, line.begin());
    transform();
    std::copy(transformed.begin(), transformed.end(), data.begin() + static_cast<std::ptrdiff_t>(y) * n);
  }
  for (int x = 0; x < n; ++x) {
    for (int y = 0; y < n; ++y) line[static_cast<std::size_t>(y)] = data[static_cast<std::size_t>(y) * n + x];
    transform();
    for (int y = 0; y < n; ++y) data[static_cast<std::size_t>(y) * n + x] = transformed[static_cast<std::size_t>(y)];
  }
}

double spectral_exponent(const Heightfield& heights) {
  int n = 1;
  while (2 * n <= std::min(heights.width(), heights.height())) n *= 2;
  if (n < 16) fail("the spectral exponent needs at least 16 x 16 samples; the heightfield has {} x {}", heights.width(), heights.height());
  const int x0 = (heights.width() - n) / 2, y0 = (heights.height() - n) / 2;
  std::vector<double> square(static_cast<std::size_t>(n) * n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) square[static_cast<std::size_t>(y) * n + x] = heights(x0 + x, y0 + y);
  std::vector<std::complex<double>> spectrum = detrended_windowed(square, n);
  fft_2d(spectrum, n);
  // Power averaged in 20 bins spaced evenly in log f between 3/N and 0.25 cycles per cell.
  constexpr int bins = 20;
  const double f_low = 3.0 / n, f_high = 0.25, log_span = std::log(f_high / f_low);
  std::vector<double> power(bins, 0.0), log_f(bins, 0.0), count(bins, 0.0);
  for (int ky = 0; ky < n; ++ky)
    for (int kx = 0; kx < n; ++kx) {
      const int fx = kx < n / 2 ? kx : kx - n, fy = ky < n / 2 ? ky : ky - n;
      const double f = std::hypot(fx, fy) / n;
      if (f < f_low || f > f_high) continue;
      const int bin = std::min(bins - 1, static_cast<int>(std::log(f / f_low) / log_span * bins));
      power[bin] += std::norm(spectrum[static_cast<std::size_t>(ky) * n + kx]);
      log_f[bin] += std::log(f);
      count[bin] += 1.0;
    }
  std::vector<double> xs, ys;
  for (int bin = 0; bin < bins; ++bin)
    if (count[bin] > 0 && power[bin] > 0) xs.push_back(log_f[bin] / count[bin]), ys.push_back(std::log(power[bin] / count[bin]));
  return -fitted_slope(xs, ys);
}

LandformMeasures measure_landform(const Heightfield& heights, std::optional<double> sea_level_m, const Context& context) {
  if (heights.width() < 17 || heights.height() < 17)
    fail("landform measures need at least 17 x 17 samples; the heightfield has {} x {}", heights.width(), heights.height());
  require_routable_heights(heights);
  LandformMeasures m;
  const auto is_land = [&](float h) { return !sea_level_m || static_cast<double>(h) > *sea_level_m; };
  const auto [low, high] = std::minmax_element(heights.values().begin(), heights.values().end());
  m.relief_m = static_cast<double>(*high) - std::max(static_cast<double>(*low), sea_level_m.value_or(*low));
  const FlowRouting flow = route_flow(heights, Outlets{sea_level_m}, context);
  const double cell_area = heights.cell_size_m * heights.cell_size_m;
  const double channel_area = 0.01 * static_cast<double>(heights.size()) * cell_area, hillslope_area = 2.0 * cell_area;
  std::vector<double> channel, hillslope;
  double slope_sum = 0, curvature_sum = 0, curvature_square_sum = 0;
  long long land = 0, interior_land = 0;
  for (float h : heights.values()) land += is_land(h) ? 1 : 0;
  for (int y = 1; y + 1 < heights.height(); ++y)
    for (int x = 1; x + 1 < heights.width(); ++x) {
      const float h = heights(x, y);
      if (!is_land(h)) continue;
      ++interior_land;
      const double slope = gradient_at(heights, x, y);
      slope_sum += slope;
      const double area = flow.area_m2(x, y);
      if (area >= channel_area) channel.push_back(slope);
      if (area <= hillslope_area) hillslope.push_back(slope);
      const double laplacian =
          (static_cast<double>(heights(x + 1, y)) + heights(x - 1, y) + heights(x, y + 1) + heights(x, y - 1) - 4.0 * h) /
          heights.cell_size_m;
      curvature_sum += laplacian, curvature_square_sum += laplacian * laplacian;
      bool pit = true;
      for (int dy = -1; dy <= 1 && pit; ++dy)
        for (int dx = -1; dx <= 1 && pit; ++dx)
          if ((dx != 0 || dy != 0) && heights(x + dx, y + dy) <= h) pit = false;
      m.pits += pit ? 1 : 0;
    }
  m.land_fraction = static_cast<double>(land) / static_cast<double>(heights.size());
  if (interior_land > 0) {
    const auto count = static_cast<double>(interior_land);
    m.mean_slope = slope_sum / count;
    const double mean_curvature = curvature_sum / count;
    m.curvature_spread = std::sqrt(std::max(0.0, curvature_square_sum / count - mean_curvature * mean_curvature));
  }
  m.channel_slope = median_of(std::move(channel));
  m.hillslope_slope = median_of(std::move(hillslope));
  m.channel_ratio = m.hillslope_slope > 0 ? m.channel_slope / m.hillslope_slope : 0.0;
  m.spectral_beta = spectral_exponent(heights);
  m.edge_distance = edge_slope_distance(heights, sea_level_m);
  return m;
}

namespace {

/// The largest difference between the distribution functions of two samples (the two-sample
/// Kolmogorov-Smirnov statistic D).
double distribution_distance(std::vector<double> a, std::vector<double> b) {
  std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end());  // not ranges: the browser build's libc++ 13 lacks them
  double most = 0.0;
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const double v = std::min(a[i], b[j]);
    while (i < a.size() && a[i] <= v) ++i;
    while (j < b.size() && b[j] <= v) ++j;
    most = std::max(
        most, std::abs(static_cast<double>(i) / static_cast<double>(a.size()) - static_cast<double>(j) / static_cast<double>(b.size())));
  }
  return most;
}

}  // namespace

double edge_slope_distance(const Heightfield& heights, std::optional<double> sea_level_m) {
  constexpr int strip = 5, inside = 55;
  const int width = heights.width(), height = heights.height();
  if (std::min(width, height) < 2 * (strip + inside)) return 0.0;
  const Grid<float> slope = slope_degrees(heights);
  const auto is_land = [&](float h) { return !sea_level_m || static_cast<double>(h) > *sea_level_m; };
  double most = 0.0;
  // Each edge's sample `along` it, `depth` samples in: north, south, west, east.
  for (int edge = 0; edge < 4; ++edge) {
    const int along = edge < 2 ? width : height;
    std::vector<double> near, in;
    for (int depth = 0; depth < strip + inside; ++depth)
      for (int a = 0; a < along; ++a) {
        const int x = edge == 0 || edge == 1 ? a : edge == 2 ? depth : width - 1 - depth;
        const int y = edge == 0 ? depth : edge == 1 ? height - 1 - depth : a;
        if (is_land(heights(x, y))) (depth < strip ? near : in).push_back(slope(x, y));
      }
    if (near.size() * 2 >= static_cast<std::size_t>(along) * strip && !in.empty())
      most = std::max(most, distribution_distance(std::move(near), std::move(in)));
  }
  return most;
}

Grid<float> slope_degrees(const Heightfield& heights) {
  Grid<float> slope(heights.width(), heights.height(), 0.0f, heights.cell_size_m);
  slope.copy_metadata_from(heights);
  const int w = heights.width(), h = heights.height();
  const double cell = heights.cell_size_m;
  parallel_for(0, h, [&](int y) {
    // Central differences inside, one-sided on the edge: the samples on each side that exist,
    // over the distance between them.
    const int north = std::max(0, y - 1), south = std::min(h - 1, y + 1);
    for (int x = 0; x < w; ++x) {
      const int west = std::max(0, x - 1), east = std::min(w - 1, x + 1);
      const double dx = east > west ? (static_cast<double>(heights(east, y)) - heights(west, y)) / ((east - west) * cell) : 0.0;
      const double dy = south > north ? (static_cast<double>(heights(x, south)) - heights(x, north)) / ((south - north) * cell) : 0.0;
      slope(x, y) = static_cast<float>(std::atan(std::hypot(dx, dy)) * 180.0 / std::numbers::pi);
    }
  });
  return slope;
}

}  // namespace sansui::water

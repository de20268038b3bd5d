// Measuring the fractal dimension of subdivided surfaces (see fractal_stats.hpp). Same fit as
// terrain::measure_hurst (a variogram over doubling lags), but over the samples both surfaces
// cover, since a mesh's footprint is rarely a rectangle.
#include "mesh/fractal_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/line_fit.hpp"
#include "mesh/rasterize.hpp"

namespace sansui::mesh {
namespace {

/// Mean squared difference of covered samples `lag` apart along rows and columns (NaN: not covered).
std::pair<double, long long> masked_variogram(const Heightfield& h, int lag) {
  double sum = 0.0;
  long long count = 0;
  for (int y = 0; y < h.height(); ++y)
    for (int x = 0; x < h.width(); ++x) {
      const float here = h(x, y);
      if (std::isnan(here)) continue;
      if (x + lag < h.width() && !std::isnan(h(x + lag, y))) {
        const double d = double(h(x + lag, y)) - here;
        sum += d * d, ++count;
      }
      if (y + lag < h.height() && !std::isnan(h(x, y + lag))) {
        const double d = double(h(x, y + lag)) - here;
        sum += d * d, ++count;
      }
    }
  return {count > 0 ? sum / double(count) : 0.0, count};
}

}  // namespace

std::optional<FractalMeasurement> measure_fractal(const TriangleMesh& coarse, const TriangleMesh& detailed, double coarse_edge_m, int steps,
                                                  int max_side) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  if (steps < 1 || steps > 30 || !(coarse_edge_m > 0.0)) return std::nullopt;
  const double cell = std::max(std::ldexp(coarse_edge_m, -steps), square_frame(detailed, max_side).cell_size_m);
  const RasterFrame frame = frame_with_cell(detailed, cell);
  FractalMeasurement m;
  m.cell_size_m = frame.cell_size_m;
  // From two cells (within one cell the raster is linear in the finest triangles) up to a sixteenth of the coarse edges: nearer the coarse
  // edges the detail levels off, since coarser shapes were subtracted with the input.
  m.min_lag = 2;
  m.max_lag = m.min_lag;
  while (2.0 * m.max_lag * frame.cell_size_m <= coarse_edge_m / 16.0 && 2 * m.max_lag < std::min(frame.width, frame.height) / 2)
    m.max_lag *= 2;
  if (m.max_lag < 4 * m.min_lag) return std::nullopt;  // fewer than three lags: no fit worth the name

  Heightfield detail = rasterize(detailed, frame, nan);
  const Heightfield base = rasterize(coarse, frame, nan);
  double sum_squares = 0.0;
  long long covered = 0;
  for (std::size_t i = 0; i < detail.size(); ++i) {
    detail.data()[i] -= base.data()[i];  // NaN where either is not covered
    if (!std::isnan(detail.data()[i])) sum_squares += double(detail.data()[i]) * detail.data()[i], ++covered;
  }
  if (covered < 64) return std::nullopt;
  m.detail_rms_m = std::sqrt(sum_squares / double(covered));

  std::vector<double> xs, ys;
  for (int lag = m.min_lag; lag <= m.max_lag; lag *= 2) {
    const auto [v, pairs] = masked_variogram(detail, lag);
    if (v <= 0.0 || pairs < 16) continue;
    xs.push_back(std::log(double(lag)));
    ys.push_back(std::log(v));
  }
  if (xs.size() < 3) return std::nullopt;
  const LineFit fit = fit_line(xs, ys);
  m.measured_h = fit.slope / 2.0;
  m.r_squared = fit.r_squared;
  return m;
}

}  // namespace sansui::mesh

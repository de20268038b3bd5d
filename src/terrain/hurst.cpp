#include "terrain/hurst.hpp"

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "core/line_fit.hpp"

namespace sansui::terrain {
namespace {

/// Mean squared difference of samples `lag` apart, along rows and along columns.
double variogram(ConstGridView<float> h, int lag) {
  double sum = 0.0;
  long long count = 0;
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) {
      if (x + lag < h.width) {
        const double d = double(h(x + lag, y)) - h(x, y);
        sum += d * d, ++count;
      }
      if (y + lag < h.height) {
        const double d = double(h(x, y + lag)) - h(x, y);
        sum += d * d, ++count;
      }
    }
  return count > 0 ? sum / double(count) : 0.0;
}

}  // namespace

VariogramFit measure_hurst(ConstGridView<float> heights, int min_lag, int max_lag) {
  if (min_lag < 1 || max_lag < 2 * min_lag || max_lag >= std::min(heights.width, heights.height))
    fail("variogram lags {}..{} do not fit a {}x{} grid", min_lag, max_lag, heights.width, heights.height);
  std::vector<double> xs, ys;
  for (int lag = min_lag; lag <= max_lag; lag *= 2) {
    const double v = variogram(heights, lag);
    if (v <= 0.0) continue;
    xs.push_back(std::log(double(lag)));
    ys.push_back(std::log(v));
  }
  if (xs.size() < 2) return {};
  const LineFit fit = fit_line(xs, ys);
  return {fit.slope / 2.0, fit.r_squared};
}

}  // namespace sansui::terrain

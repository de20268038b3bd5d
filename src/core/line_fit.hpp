// Least-squares straight lines, for the log-log fits that measure roughness (variograms,
// power spectra) in terrain/, mesh/ and contour/.
#pragma once

#include <cmath>
#include <span>

namespace sansui {

struct LineFit {
  double slope = 0.0;
  double intercept = 0.0;
  double r_squared = 0.0;  ///< 0 when x does not vary
};

/// The line y = slope * x + intercept closest to the points in the least-squares sense.
inline LineFit fit_line(std::span<const double> x, std::span<const double> y) {
  const std::size_t count = std::min(x.size(), y.size());
  if (count < 2) return {};
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < count; ++i) mx += x[i], my += y[i];
  mx /= double(count), my /= double(count);
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    const double dx = x[i] - mx, dy = y[i] - my;
    sxx += dx * dx, sxy += dx * dy, syy += dy * dy;
  }
  if (!(sxx > 0.0)) return {0.0, my, 0.0};
  const double slope = sxy / sxx;
  return {slope, my - slope * mx, syy > 0.0 ? sxy * sxy / (sxx * syy) : 1.0};
}

}  // namespace sansui

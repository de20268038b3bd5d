// The arithmetic of one cell of the erosion chain's stages after stream power (erode.cpp), shared
// with the tiled chain (tiled_erosion.cpp), which must give the same bytes. Heights are read
// through at(x, y) in world coordinates, so a tile's window serves as well as the whole grid.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/exact_sum.hpp"

namespace sansui::water {

/// Thermal iterations after stream-power step `step` of `steps`: `total` spread evenly, the
/// first steps taking one more when it does not divide.
inline int thermal_share(int total, int step, int steps) {
  return total / steps + (step < total % steps ? 1 : 0);
}

/// follow_inner_land (erosion_chain.hpp) on one edge cell: above base level, it is lowered to its
/// inward neighbour when that is lower, never below base level. Water leaves the map at its edge,
/// so the edge must wear down with the land it drains; as fixed base level it would stand as a
/// wall around a worn-down plain.
inline void follow_inner(float& edge, float inner, double base_level) {
  if (static_cast<double>(edge) > base_level && inner < edge) edge = static_cast<float>(std::max<double>(inner, base_level));
}

/// The lowest a cell may go after droplets and kept detail, when it was `settled` before them:
/// base level, or its settled height where that was lower. Droplets change the four cells around
/// them, so one on the foot of a slope would dig into the sea or the plain beside it, and
/// roughness put back on the lowest land would dip under base level.
inline float settled_floor(float settled, double base_level) {
  return static_cast<float>(std::min<double>(settled, base_level));
}

/// Gradient at (x, y) of a width x height grid by central differences (one-sided on the edge).
/// [Units: m/m]
template <class At>
double gradient_at(At&& at, int x, int y, int width, int height, double cell_size_m) {
  const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, width - 1), y0 = std::max(y - 1, 0), y1 = std::min(y + 1, height - 1);
  const double dx = (static_cast<double>(at(x1, y)) - at(x0, y)) / (std::max(1, x1 - x0) * cell_size_m);
  const double dy = (static_cast<double>(at(x, y1)) - at(x, y0)) / (std::max(1, y1 - y0) * cell_size_m);
  return std::hypot(dx, dy);
}

/// The root mean square from an exact sum of squares over `count` cells (0 without cells).
inline double root_mean_square(const ExactSum& squares, std::int64_t count) {
  return count > 0 ? std::sqrt(squares.value() / static_cast<double>(count)) : 0.0;
}

/// Slope under which land keeps less of its roughness (none on the flat, all from 4.6 degrees up).
inline constexpr double plain_slope = 0.08;

/// What keep_detail adds to a cell: its `detail` times `weight`, fully on hillslopes, fading to
/// nothing where the rivers cut 30 times the detail's typical `size`, on gentle ground (flood and
/// coastal plains stay smooth, instead of a field of puddles), and within 3 times its size of
/// base level (the coast is not speckled with islets).
inline float kept_detail(double weight, double size, float incised_m, float detail, double above_base, double gradient) {
  const double channel = std::clamp(1.0 - static_cast<double>(incised_m) / (30.0 * size), 0.0, 1.0);
  const double coast = std::clamp(above_base / (3.0 * size), 0.0, 1.0);
  const double hillslope = std::clamp(gradient / plain_slope, 0.0, 1.0);
  return static_cast<float>(weight * channel * coast * hillslope * static_cast<double>(detail));
}

/// The two samples of every 2^levels-th around position i of n, and where i lies between them.
struct Bracket {
  int low, high;
  float t;
};
inline Bracket bracket(int i, int step, int n) {
  int low = i / step * step;
  if (low >= n - 1) low = std::max(0, n - 1 - step);
  const int high = std::min(low + step, n - 1);
  return {low, high, high > low ? static_cast<float>(i - low) / static_cast<float>(high - low) : 0.0f};
}

/// fine_detail (erode.hpp) at (x, y) of a width x height grid larger than 2^levels each way:
/// the height minus its bilinear interpolation from every 2^levels-th sample, all within 2^levels
/// samples of (x, y).
template <class At>
float fine_detail_at(At&& at, int x, int y, int width, int height, int levels) {
  const int step = 1 << levels;
  const Bracket bx = bracket(x, step, width), by = bracket(y, step, height);
  const float top = at(bx.low, by.low) * (1 - bx.t) + at(bx.high, by.low) * bx.t;
  const float bottom = at(bx.low, by.high) * (1 - bx.t) + at(bx.high, by.high) * bx.t;
  return at(x, y) - (top * (1 - by.t) + bottom * by.t);
}

}  // namespace sansui::water

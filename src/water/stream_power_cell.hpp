// The arithmetic of one cell of a stream-power step and of its hillslope diffusion, shared by the
// whole-grid step (stream_power.cpp) and the tiled one (tiled_erosion.cpp), which must give the
// same bytes: the two orders of work call the same per-cell code.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "water/neighbours.hpp"

namespace sansui::water {

/// x > 0 with x + f x^n = x0 (x: the height above the receiver after the step), by Newton's
/// method from x0, where the function is positive; halving instead of stepping below zero.
inline double solve_incision(double x0, double f, double n) {
  double x = x0;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double power = std::pow(x, n - 1.0);
    const double g = x + f * power * x - x0;
    const double slope = 1.0 + f * n * power;
    double next = x - g / slope;
    if (next <= 0.0) next = 0.5 * x;
    const bool converged = std::abs(next - x) <= 1e-12 * x0;
    x = next;
    if (converged) break;
  }
  return x;
}

/// The diffusion's backward Euler along one line of cells, by the Thomas algorithm:
/// (1 + 2 alpha) z_i - alpha (z_{i-1} + z_{i+1}) = z_i^old at free cells, z_i = z_i^old at fixed
/// ones; every line starts and ends fixed. The forward elimination of cell i from its
/// predecessor's (cp, dp): the cell's own (cp, dp).
struct ThomasStep {
  double cp = 0.0, dp = 0.0;
};
inline ThomasStep thomas_forward(double alpha, bool fixed, double z, ThomasStep previous) {
  if (fixed) return {0.0, z};
  const double m = 1.0 + 2.0 * alpha + alpha * previous.cp;
  return {-alpha / m, (z + alpha * previous.dp) / m};
}
/// The back substitution of cell i from its successor's solved value: cell i's value.
inline double thomas_back(ThomasStep step, double next) {
  return step.dp - step.cp * next;
}

/// True if a receiver at index offset `offset` from its cell (always one of the eight
/// neighbours) lies diagonally: neither beside it in its row nor above or below it. No division,
/// which cost as much as the rest of the incision of a cell.
inline bool is_diagonal(CellIndex offset, int width) {
  return offset != 1 && offset != -1 && offset != width && offset != -width;
}

/// Drainage area to the power m, the small areas (most cells) from a table of pow of the very
/// same arguments: the same bytes as pow, without its cost on every cell.
class AreaPower {
 public:
  AreaPower(double cell_area, double exponent) : cell_area_(cell_area), exponent_(exponent) {
    for (std::size_t k = 1; k < table_size; ++k) area_[k] = static_cast<double>(k) * cell_area, power_[k] = std::pow(area_[k], exponent);
  }
  double operator()(double area) const {
    const double cells = area / cell_area_;
    if (cells > 0.5 && cells < table_size - 1) {
      const auto k = static_cast<std::size_t>(cells + 0.5);
      if (area_[k] == area) return power_[k];
    }
    return std::pow(area, exponent_);
  }

 private:
  static constexpr std::size_t table_size = 2048;
  double cell_area_, exponent_;
  std::array<double, table_size> area_{}, power_{};
};

}  // namespace sansui::water

// Thermal erosion (see thermal.hpp).
#include "water/thermal.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/parallel.hpp"
#include "water/neighbours.hpp"

namespace sansui::water {
namespace {

/// For each cell i of row y (column x): start(i), then visit(i, k, j) for each of its neighbours
/// j (direction k) inside the map, then done(x, i).
template <class Start, class Visit, class Done>
void each_neighbour_of_row(const Heightfield& z, int y, Start&& start, Visit&& visit, Done&& done) {
  const int width = z.width(), height = z.height();
  const auto offsets = neighbour_offsets(width);
  const bool inner_row = y > 0 && y < height - 1;
  for (int x = 0; x < width; ++x) {
    const std::size_t i = static_cast<std::size_t>(y) * width + x;
    const bool inner = inner_row && x > 0 && x < width - 1;
    start(i);
    for (std::size_t k = 0; k < 8; ++k) {
      if (!inner) {
        const int nx = x + neighbour_dx[k], ny = y + neighbour_dy[k];
        if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
      }
      visit(i, k, static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + offsets[k]));
    }
    done(x, i);
  }
}

/// Per cell of the previous heights: the height it sends away and, so that the receivers can
/// work out their share, the sum of its excess drops. A cell with excesses d_k over its lower
/// neighbours sends rate * max(d) in total, split in proportion to d_k (Olsen 2004).
void shed(const Heightfield& z, int y, const std::array<double, 8>& limit, double rate, double* send, double* total_excess) {
  const float* heights = z.data();
  double largest = 0.0, sum = 0.0;
  each_neighbour_of_row(
      z, y, [&](std::size_t) { largest = 0.0, sum = 0.0; },
      [&](std::size_t i, std::size_t k, std::size_t j) {
        const double excess = static_cast<double>(heights[i]) - heights[j] - limit[k];
        if (excess > 0.0) largest = std::max(largest, excess), sum += excess;
      },
      [&](int x, std::size_t) {
        send[x] = rate * largest;
        total_excess[x] = sum;
      });
}

/// The new height of the cells of row y: what they keep plus what each higher neighbour sends
/// them, its share of its own total excess.
void gather(const Heightfield& z, int y, const std::array<double, 8>& limit, const double* send, const double* total_excess, float* out) {
  const float* heights = z.data();
  double change = 0.0;
  each_neighbour_of_row(
      z, y, [&](std::size_t i) { change = -send[i]; },
      [&](std::size_t i, std::size_t k, std::size_t j) {
        const double excess = static_cast<double>(heights[j]) - heights[i] - limit[k];  // the same distance back
        if (excess > 0.0) change += send[j] * (excess / total_excess[j]);
      },
      [&](int x, std::size_t i) { out[x] = static_cast<float>(static_cast<double>(heights[i]) + change); });
}

}  // namespace

Heightfield erode_thermal(const Heightfield& heights, const ThermalParams& params, const Context& context) {
  params.validate();
  require_finite_heights(heights, "thermal erosion");
  const int width = heights.width(), height = heights.height();
  // tan(talus) * distance: the largest drop to each neighbour that stays at rest.
  std::array<double, 8> limit{};
  const double tangent = std::tan(params.talus_angle_deg * std::numbers::pi / 180.0);
  for (std::size_t k = 0; k < 8; ++k) limit[k] = tangent * neighbour_distance[k] * heights.cell_size_m;
  Heightfield current(heights), next(heights);
  std::vector<double> send(heights.size()), total_excess(heights.size());
  for (int iteration = 0; iteration < params.iterations; ++iteration) {
    context.check_cancelled();
    parallel_for_ranges<int>(0, height, 16, [&](int rows_begin, int rows_end) {
      for (int y = rows_begin; y < rows_end; ++y) {
        const std::size_t row = static_cast<std::size_t>(y) * width;
        shed(current, y, limit, params.rate, send.data() + row, total_excess.data() + row);
      }
    });
    parallel_for_ranges<int>(0, height, 16, [&](int rows_begin, int rows_end) {
      for (int y = rows_begin; y < rows_end; ++y) gather(current, y, limit, send.data(), total_excess.data(), next.row(y).data());
    });
    std::swap(current, next);
    context.report("thermal erosion", static_cast<double>(iteration + 1) / params.iterations);
  }
  return current;
}

}  // namespace sansui::water

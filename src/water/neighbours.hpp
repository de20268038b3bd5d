// The eight neighbours of a grid cell, in one fixed order (east, then clockwise), shared by every
// water stage so that ties are always broken the same way.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "core/grid.hpp"

namespace sansui::water {

inline constexpr std::array<int, 8> neighbour_dx = {1, 1, 0, -1, -1, -1, 0, 1};
inline constexpr std::array<int, 8> neighbour_dy = {0, 1, 1, 1, 0, -1, -1, -1};
/// Distance to each neighbour in cells.
inline constexpr std::array<double, 8> neighbour_distance = {1.0, 1.4142135623730951, 1.0, 1.4142135623730951,
                                                             1.0, 1.4142135623730951, 1.0, 1.4142135623730951};

/// Index offsets of the eight neighbours in a row-major grid of the given width.
inline std::array<std::ptrdiff_t, 8> neighbour_offsets(int width) {
  std::array<std::ptrdiff_t, 8> offsets{};
  for (std::size_t k = 0; k < 8; ++k) offsets[k] = static_cast<std::ptrdiff_t>(neighbour_dy[k]) * width + neighbour_dx[k];
  return offsets;
}

/// True for a cell on the map's outer ring.
inline bool on_edge(int x, int y, int width, int height) {
  return x == 0 || y == 0 || x == width - 1 || y == height - 1;
}

/// Gives `to` the cell size and origin of `from` (grids of different sample types).
template <class A, class B>
void copy_placement(Grid<A>& to, const Grid<B>& from) {
  to.cell_size_m = from.cell_size_m, to.origin_x_m = from.origin_x_m, to.origin_y_m = from.origin_y_m;
}

/// Makes `grid` width x height, keeping its memory when it has that size already (its samples are
/// then left as they were; otherwise they are unset).
template <class T>
void ensure_shape(Grid<T>& grid, int width, int height) {
  if (grid.width() != width || grid.height() != height) grid = Grid<T>::uninitialized(width, height, grid.cell_size_m);
}

/// Throws InputError if `heights` holds NaN or infinity: every water stage needs finite heights.
inline void require_finite_heights(const Grid<float>& heights, std::string_view stage) {
  for (float h : heights.values())
    if (!std::isfinite(h)) fail("the heightfield holds a value that is not a finite number; {} needs finite heights", stage);
}

/// Cells as 32-bit indices: 4097 x 4097 fits many times over, and halves the memory of the stacks.
using CellIndex = std::int32_t;

/// Largest grid the water stages accept (cells): indices stay below 2^31.
inline constexpr std::size_t max_cells = std::size_t{1} << 30;

/// Throws InputError if `heights` cannot be routed: too many cells, or a value that is not finite.
inline void require_routable_heights(const Grid<float>& heights) {
  if (heights.size() > max_cells) fail("the heightfield has {} cells; flow routing takes at most {}", heights.size(), max_cells);
  require_finite_heights(heights, "flow routing");
}

/// Floats as unsigned integers in the same order (IEEE 754 total order of non-NaN values), so a
/// height can lead a sort or heap key.
inline std::uint32_t ordered_bits(float v) {
  const auto u = std::bit_cast<std::uint32_t>(v);
  return (u & 0x80000000u) != 0 ? ~u : (u | 0x80000000u);
}

}  // namespace sansui::water

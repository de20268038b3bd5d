// Where the samples of a Heightfield stand in the contours' plane (x east, y north, metres).
// Grid convention (core/grid.hpp): sample (i, j) stands at east = origin_x + i * cell and
// south = origin_y + j * cell, so north = -(origin_y + j * cell): row 0 is the northern edge.
#pragma once

#include "contour/geometry.hpp"
#include "core/grid.hpp"

namespace sansui::contour {

struct GridFrame {
  double origin_x_m = 0.0;
  double origin_y_m = 0.0;  ///< south coordinate of row 0
  double cell_m = 1.0;

  template <class T>
  static GridFrame of(const Grid<T>& grid) {
    return {grid.origin_x_m, grid.origin_y_m, grid.cell_size_m};
  }
  double east(double column) const { return origin_x_m + column * cell_m; }
  double north(double row) const { return -(origin_y_m + row * cell_m); }
  Point at(double column, double row) const { return {east(column), north(row)}; }
  double column(double east_m) const { return (east_m - origin_x_m) / cell_m; }
  double row(double north_m) const { return (-north_m - origin_y_m) / cell_m; }
};

}  // namespace sansui::contour

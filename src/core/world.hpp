// The world every node of a recipe receives (docs/architecture.md, "one world"): its grid (samples
// across and down, the distance between them, where sample (0, 0) stands) and its sea level. A
// node makes its grid on the world's; no params struct keeps a copy of these facts.
#pragma once

#include <array>

namespace sansui {

struct World {
  int width = 1025;      ///< samples across (west to east); 0: the grid is its source's (has_grid())
  int height = 1025;     ///< samples down (north to south)
  double cell_m = 10.0;  ///< distance between samples. [Units: m]
  /// Where sample (0, 0) stands, east and south, as a Grid's origin_x_m and origin_y_m. [Units: m]
  double origin_x_m = 0.0, origin_y_m = 0.0;
  double sea_level_m = 0.0;  ///< [Units: m]

  /// Whether the grid is known. A world without one takes the grid of what its sources read or
  /// grow (a heightmap file's own size, cell and place).
  bool has_grid() const { return width > 0 && height > 0; }
  bool square() const { return width == height; }
  double cells() const { return static_cast<double>(width) * static_cast<double>(height); }
  /// The middle of the grid, east and north of sample (0, 0) (north is negative below it, as in
  /// every output's GeoJSON): where a node puts what it places by default. [Units: m]
  std::array<double, 2> centre_m() const { return {0.5 * (width - 1) * cell_m, -0.5 * (height - 1) * cell_m}; }
};

}  // namespace sansui

// A DEM from any given contour map (issue 17 item 6): open or closed lines with elevations, and
// optional spot heights, as digitised maps or gdal_contour give them. Like GRASS r.surf.contour,
// each cell is interpolated between the contours that bracket it by its distances to them,
// z = z_low + (z_high - z_low) * d_low / (d_low + d_high), but fast:
//   1. every line is drawn into the grid (8-connected; each cell keeps its nearest segment);
//   2. the cells no line passes through fall into 4-connected regions; the lines around a
//      region give its bracket: the lowest and highest level on its border;
//   3. the distances to the two bracketing levels come from exact Euclidean feature transforms
//      (edt.hpp), one per class of level rank modulo 4, measured to the segment itself;
//   4. a region bordered by one level only (inside a summit or a depression contour, or cut by
//      the map's edge) is a dome or a bowl: it leaves its contour with the slope of the ground
//      outside it (the mean spacing of the neighbouring region's contours) and flattens at its
//      centre, z = z_c +- h (2t - t^2), t = d / d_max, h = min(slope d_max / 2, 0.9 interval),
//      so it never reaches the next level; a spot height inside sets h;
//   5. the cells a line passes through take the line's level plus the slope of their side times
//      their distance to it, so the contours leave no rows of equal cells (no terraces).
// Every cell lies between its bracketing levels. Same result with any number of threads.
#pragma once

#include <vector>

#include "contour/geometry.hpp"
#include "core/budget.hpp"
#include "core/context.hpp"
#include "core/contour_lines.hpp"
#include "core/grid.hpp"

namespace sansui::contour {

// The map itself is plain data in core (core/contour_lines.hpp).
using sansui::ContourLine;
using sansui::ContourMap;
using sansui::SpotHeight;

/// The grid: samples per side, cell size and the position of sample (0, 0) (grid_frame.hpp).
/// The most samples a side of a DEM interpolated from contours (a contour map, or a contour
/// mountain's): its working arrays are several times the grid.
inline constexpr int max_contour_dem_side = 32768;

struct ContourMapGrid {
  int width = 0, height = 0;
  double cell_m = 1.0;
  double origin_x_m = 0.0, origin_y_m = 0.0;
};

/// The grid over the map's extent (lines and spots): `cell_m` if > 0, else the cell that puts
/// `samples` samples along the longer side; the extent's corners are samples. InputError if the
/// map is empty or the grid would exceed 32768 samples a side.
ContourMapGrid contour_map_grid(const ContourMap& map, int samples, double cell_m);

/// What contour_map_to_dem needs for `grid`: its working arrays are about 7 times the DEM it
/// returns (measured with `sansui contour-dem`: 26 bytes a cell), 0.3 microseconds a cell.
budget::Cost contour_map_dem_cost(const ContourMapGrid& grid);

/// Interpolates the DEM (see above). InputError for an empty map, a non-finite elevation or
/// coordinate, or a bad grid, or when contour_map_dem_cost() does not fit the budget
/// (budget::check), before any grid is allocated.
Heightfield contour_map_to_dem(const ContourMap& map, const ContourMapGrid& grid, const Context& context = quiet_context());

}  // namespace sansui::contour

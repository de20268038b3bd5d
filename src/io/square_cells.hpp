// Resampling a grid of rectangular cells (a GeoTIFF whose pixel scale differs in x and y) to
// square cells, for readers (issue 17 item 7). Internal to io/.
#pragma once

#include "core/grid.hpp"

namespace sansui::io::detail {

/// `heights` (samples cell_x_m apart east-west, cell_y_m apart north-south, origin at sample
/// (0, 0)) resampled bilinearly to square cells of the smaller of the two over the same extent:
/// no sample is lost, the first row and column keep their positions. The result's cell size and
/// origin are set. [Units: m] [Range: cell sizes > 0]
Heightfield resample_to_square_cells(const Heightfield& heights, double cell_x_m, double cell_y_m);

}  // namespace sansui::io::detail

// Exact Euclidean distance (feature) transform on a grid, in linear time:
//   A. Meijster, J. Roerdink, W. Hesselink, "A general algorithm for computing distance
//   transforms in linear time" (2000), phase 1 (nearest source along columns, two scans); and
//   P. Felzenszwalb, D. Huttenlocher, "Distance transforms of sampled functions" (2012), the
//   lower envelope of parabolas along rows for phase 2, which also tells which source won.
// Columns are scanned row by row (the inner loop runs along memory and vectorises), rows are
// processed in parallel; the result does not depend on the number of threads.
#pragma once

#include <cstdint>

#include "core/grid.hpp"

namespace sansui::contour {

/// For every cell, the index (y * width + x) of the nearest cell where `is_source` is non-zero
/// (Euclidean distance between cell centres; ties go to the smaller column, then row), or -1
/// if there is no source at all.
void nearest_source(const Grid<std::uint8_t>& is_source, Grid<std::int32_t>& nearest);

}  // namespace sansui::contour

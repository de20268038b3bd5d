// Filling a DEM's NoData cells (voids in SRTM, the sea in a coastal tile, a clipped edge): each
// takes the height of its nearest valid cell, by rings of 4-neighbours outward from the valid
// cells (a multi-source breadth-first search: linear time, the same bytes on every run). Plain
// and flat, so that a void never makes a pit or a spike; the caller notes how many were filled.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/grid.hpp"

namespace sansui::io::detail {

/// Fills every cell of `heights` whose `missing` flag is set (row-major, one per cell) from its
/// nearest valid cell, ties broken in scan order. Returns how many cells were filled. Throws
/// InputError naming `what` when no cell is valid.
std::size_t fill_no_data(Heightfield& heights, const std::vector<std::uint8_t>& missing, const char* what);

/// "NAME: 1,234 of 1,048,576 samples (0.12 %) were NoData; each took the height of its nearest
/// valid sample".
std::string no_data_note(const std::string& name, std::size_t filled, std::size_t samples);

}  // namespace sansui::io::detail

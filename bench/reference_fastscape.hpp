// A plain, serial FastScape step (Braun & Willett 2013): the erosion benchmark's in-tree
// reference. See reference_fastscape.cpp.
#pragma once

#include <vector>

namespace sansui::reference {

/// One implicit stream-power step (n = 1, no uplift) of the row-major heights `z` in place: D8
/// receivers, stack, drainage area, incision. The edge and cells at or below `sea_level` are
/// base level; pits are their own receivers.
void fastscape_step(std::vector<float>& z, int width, int height, double cell_m, double k_dt, double m, double sea_level);

}  // namespace sansui::reference

// A quick look at a DEM without a GPU: top-down shaded relief (Horn's slopes, light from the
// north-west, 45 degrees up) over a hypsometric tint, north up. `sansui subdivide --preview`
// writes it; `sansui render` draws the full picture.
#pragma once

#include "core/color.hpp"
#include "core/grid.hpp"

namespace sansui::mesh {

/// One pixel per sample. `exaggeration` scales slopes before shading. [Range: > 0] [Default: 1]
Image shaded_relief(const Heightfield& heights, double exaggeration = 1.0);

}  // namespace sansui::mesh

// Optional per-sample inputs drawn on the terrain besides its heights.
#pragma once

#include "core/color.hpp"

namespace sansui::render {

/// Not owned: read while the terrain is uploaded (TerrainRenderer::set_terrain) only.
struct TerrainLayers {
  /// Colour of bare rock per sample (e.g. rock strata evaluated from a solid texture at the
  /// surface, a later issue), shown instead of palette.cliff on cliffs and above the tree line.
  /// Any size: it is stretched over the terrain's extent (sample (0, 0) at the north-west
  /// corner) and thinned to max_texture_samples per side. sRGB; alpha is ignored.
  /// [Default: none, the palette's cliff colour]
  const Image* cliff_albedo = nullptr;
};

}  // namespace sansui::render

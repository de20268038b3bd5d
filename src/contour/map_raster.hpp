// The contour map as an RGBA picture (see map_drawing.hpp): anti-aliased strokes (coverage from
// the distance to each segment), polygon fills (4x4 samples per pixel) and labels in a small
// built-in stroke font (digits, '.', '-', ' ', 'k', 'm', 'N': all a contour map prints).
#pragma once

#include "contour/map_drawing.hpp"
#include "core/color.hpp"

namespace sansui::contour {

Image rasterize_map(const MapDrawing& map);

}  // namespace sansui::contour

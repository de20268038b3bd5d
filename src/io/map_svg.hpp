// The contour map as SVG text (core/map_drawing.hpp). Strokes become paths, labels text with a
// halo (paint-order="stroke"), fills polygons.
#pragma once

#include <string>

#include "core/map_drawing.hpp"

namespace sansui::io {

std::string map_to_svg(const MapDrawing& map);

}  // namespace sansui::io

// The contour map as SVG text (see map_drawing.hpp). Strokes become paths, labels text with a
// halo (paint-order="stroke"), fills polygons.
#pragma once

#include <string>

#include "contour/map_drawing.hpp"

namespace sansui::contour {

std::string map_to_svg(const MapDrawing& map);

}  // namespace sansui::contour

// The contour map as SVG text (see contour/map_drawing.hpp). Strokes become paths, labels text with a
// halo (paint-order="stroke"), fills polygons.
#pragma once

#include <string>

#include "contour/map_drawing.hpp"

namespace sansui::io {

std::string map_to_svg(const contour::MapDrawing& map);

}  // namespace sansui::io

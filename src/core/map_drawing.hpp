// A map as a small display list in pixels (x right, y down): strokes, fills and labels painted in
// order. contour lays out its contour maps as one (contour/map_drawing.hpp); io writes it as SVG
// (io/map_svg.hpp) and render-free code rasterises it, so both pictures agree.
#pragma once

#include <string>
#include <variant>
#include <vector>

#include "core/color.hpp"
#include "core/plane_point.hpp"

namespace sansui {

/// Polyline or polygon outline in pixels.
struct MapStroke {
  std::vector<PlanePoint> points;
  bool closed = true;
  double width_px = 1.0;
  Rgba8 colour;
};
/// A filled polygon in pixels.
struct MapFill {
  std::vector<PlanePoint> points;
  Rgba8 colour;
};
/// Text centred at `at`, turned by `angle_deg` (clockwise on screen), with a halo behind it.
struct MapLabel {
  PlanePoint at;
  double angle_deg = 0.0;
  double size_px = 12.0;  ///< height of a digit
  std::string text;
  Rgba8 colour;
  Rgba8 halo{255, 255, 255, 255};
};
using MapItem = std::variant<MapStroke, MapFill, MapLabel>;

struct MapDrawing {
  int width_px = 0;
  int height_px = 0;
  Rgba8 background{255, 255, 255, 255};
  std::vector<MapItem> items;  ///< painted in order
};

}  // namespace sansui

#include "contour/map_raster.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sansui::contour {
namespace {

using Polyline = std::vector<Point>;

/// Glyphs in a box 0.6 wide and 1 tall (y down), as polylines.
std::vector<Polyline> glyph(char c) {
  switch (c) {
    case '0':
      return {{{0.3, 0}, {0.5, 0.1}, {0.56, 0.5}, {0.5, 0.9}, {0.3, 1}, {0.1, 0.9}, {0.04, 0.5}, {0.1, 0.1}, {0.3, 0}}};
    case '1':
      return {{{0.13, 0.2}, {0.33, 0}, {0.33, 1}}};
    case '2':
      return {{{0.06, 0.2}, {0.18, 0.03}, {0.4, 0.02}, {0.53, 0.18}, {0.5, 0.4}, {0.05, 1}, {0.56, 1}}};
    case '3':
      return {{{0.07, 0.1}, {0.3, 0}, {0.5, 0.12}, {0.5, 0.35}, {0.26, 0.48}, {0.52, 0.62}, {0.53, 0.88}, {0.3, 1}, {0.05, 0.9}}};
    case '4':
      return {{{0.42, 1}, {0.42, 0}, {0.03, 0.7}, {0.58, 0.7}}};
    case '5':
      return {{{0.52, 0}, {0.1, 0}, {0.07, 0.45}, {0.3, 0.38}, {0.5, 0.5}, {0.54, 0.75}, {0.4, 0.95}, {0.22, 1}, {0.05, 0.9}}};
    case '6':
      return {{{0.5, 0.08},
               {0.3, 0},
               {0.12, 0.15},
               {0.05, 0.55},
               {0.1, 0.9},
               {0.3, 1},
               {0.5, 0.9},
               {0.54, 0.68},
               {0.4, 0.5},
               {0.25, 0.48},
               {0.07, 0.6}}};
    case '7':
      return {{{0.05, 0}, {0.56, 0}, {0.22, 1}}};
    case '8':
      return {{{0.3, 0.47},
               {0.1, 0.35},
               {0.1, 0.12},
               {0.3, 0},
               {0.5, 0.12},
               {0.5, 0.35},
               {0.3, 0.47},
               {0.07, 0.6},
               {0.06, 0.85},
               {0.3, 1},
               {0.54, 0.85},
               {0.53, 0.6},
               {0.3, 0.47}}};
    case '9':
      return {{{0.5, 0.4},
               {0.35, 0.52},
               {0.15, 0.5},
               {0.05, 0.3},
               {0.12, 0.07},
               {0.3, 0},
               {0.48, 0.1},
               {0.55, 0.45},
               {0.48, 0.85},
               {0.3, 1},
               {0.1, 0.92}}};
    case '.':
      return {{{0.27, 0.96}, {0.33, 0.96}}};
    case '-':
      return {{{0.1, 0.55}, {0.5, 0.55}}};
    case 'm':
      return {{{0.05, 1}, {0.05, 0.55}},
              {{0.05, 0.65}, {0.15, 0.55}, {0.26, 0.58}, {0.3, 0.7}, {0.3, 1}},
              {{0.3, 0.7}, {0.36, 0.58}, {0.46, 0.55}, {0.55, 0.62}, {0.56, 1}}};
    case 'k':
      return {{{0.08, 0}, {0.08, 1}}, {{0.5, 0.5}, {0.08, 0.82}}, {{0.22, 0.72}, {0.52, 1}}};
    case 'N':
      return {{{0.07, 1}, {0.07, 0}, {0.53, 1}, {0.53, 0}}};
    default:
      return {};
  }
}

class Canvas {
 public:
  explicit Canvas(const MapDrawing& map) : image_(map.width_px, map.height_px, map.background) {}
  Image take() { return std::move(image_); }

  void blend(int x, int y, Rgba8 c, double coverage) {
    if (coverage <= 0.0 || x < 0 || y < 0 || x >= image_.width() || y >= image_.height()) return;
    const double a = std::min(1.0, coverage) * c.a / 255.0;
    Rgba8& p = image_(x, y);
    auto mix = [a](std::uint8_t under, std::uint8_t over) { return static_cast<std::uint8_t>(std::lround(under + a * (over - under))); };
    p = {mix(p.r, c.r), mix(p.g, c.g), mix(p.b, c.b), 255};
  }

  /// One polyline: coverage is the largest over its segments, so joints are not painted twice.
  void stroke(const Polyline& points, bool closed, double width, Rgba8 colour) {
    if (points.empty()) return;
    Box box;
    for (const Point& p : points) box.add(p);
    const double pad = 0.5 * width + 1.0;
    const int x0 = std::max(0, static_cast<int>(std::floor(box.min_x - pad)));
    const int y0 = std::max(0, static_cast<int>(std::floor(box.min_y - pad)));
    const int x1 = std::min(image_.width() - 1, static_cast<int>(std::ceil(box.max_x + pad)));
    const int y1 = std::min(image_.height() - 1, static_cast<int>(std::ceil(box.max_y + pad)));
    if (x1 < x0 || y1 < y0) return;
    const int w = x1 - x0 + 1, h = y1 - y0 + 1;
    coverage_.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0f);
    const std::size_t n = points.size();
    const std::size_t segments = closed ? n : n - 1;
    const double half = 0.5 * std::max(width, 0.7);
    const double strength = std::min(1.0, width / 0.7);  // hairlines fade instead of thinning
    for (std::size_t s = 0; s < std::max<std::size_t>(segments, 1); ++s) {
      const Point a = points[s], b = points[(s + 1) % n];
      const int sx0 = std::max(x0, static_cast<int>(std::floor(std::min(a.x, b.x) - pad)));
      const int sx1 = std::min(x1, static_cast<int>(std::ceil(std::max(a.x, b.x) + pad)));
      const int sy0 = std::max(y0, static_cast<int>(std::floor(std::min(a.y, b.y) - pad)));
      const int sy1 = std::min(y1, static_cast<int>(std::ceil(std::max(a.y, b.y) + pad)));
      for (int y = sy0; y <= sy1; ++y)
        for (int x = sx0; x <= sx1; ++x) {
          const double d = distance_to_segment({x + 0.5, y + 0.5}, a, b);
          const auto c = static_cast<float>(std::clamp(half + 0.5 - d, 0.0, 1.0) * strength);
          float& slot = coverage_[static_cast<std::size_t>(y - y0) * w + (x - x0)];
          slot = std::max(slot, c);
        }
    }
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) blend(x, y, colour, coverage_[static_cast<std::size_t>(y - y0) * w + (x - x0)]);
  }

  void fill(const Polyline& polygon, Rgba8 colour) {
    Box box;
    for (const Point& p : polygon) box.add(p);
    const int x0 = std::max(0, static_cast<int>(std::floor(box.min_x))),
              x1 = std::min(image_.width() - 1, static_cast<int>(std::ceil(box.max_x)));
    const int y0 = std::max(0, static_cast<int>(std::floor(box.min_y))),
              y1 = std::min(image_.height() - 1, static_cast<int>(std::ceil(box.max_y)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        int inside = 0;
        for (int sy = 0; sy < 4; ++sy)
          for (int sx = 0; sx < 4; ++sx) inside += winding_number(polygon, {x + (sx + 0.5) / 4.0, y + (sy + 0.5) / 4.0}) != 0 ? 1 : 0;
        blend(x, y, colour, inside / 16.0);
      }
  }

  void label(const MapLabel& label) {
    const double size = label.size_px;
    const double advance = 0.62 * size;
    const double total = advance * static_cast<double>(label.text.size()) - 0.02 * size;
    const double angle = label.angle_deg * std::numbers::pi / 180.0;
    const double c = std::cos(angle), s = std::sin(angle);
    std::vector<Polyline> strokes;
    for (std::size_t i = 0; i < label.text.size(); ++i)
      for (Polyline line : glyph(label.text[i])) {
        for (Point& p : line) {
          const Point local{-0.5 * total + advance * static_cast<double>(i) + p.x * size, (p.y - 0.5) * size};
          p = {label.at.x + c * local.x - s * local.y, label.at.y + s * local.x + c * local.y};
        }
        strokes.push_back(std::move(line));
      }
    const double width = std::max(1.0, 0.13 * size);
    for (const Polyline& line : strokes) stroke(line, false, width + 3.0, label.halo);
    for (const Polyline& line : strokes) stroke(line, false, width, label.colour);
  }

 private:
  Image image_;
  std::vector<float> coverage_;
};

}  // namespace

Image rasterize_map(const MapDrawing& map) {
  Canvas canvas(map);
  for (const MapItem& item : map.items) {
    if (const auto* stroke = std::get_if<MapStroke>(&item)) {
      canvas.stroke(stroke->points, stroke->closed, stroke->width_px, stroke->colour);
    } else if (const auto* fill = std::get_if<MapFill>(&item)) {
      canvas.fill(fill->points, fill->colour);
    } else if (const auto* text = std::get_if<MapLabel>(&item)) {
      canvas.label(*text);
    }
  }
  return canvas.take();
}

}  // namespace sansui::contour

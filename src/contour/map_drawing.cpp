// Contour map layout: see map_drawing.hpp.
#include "contour/map_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace sansui::contour {
namespace {

/// A "nice" length (1, 2 or 5 times a power of ten) not above `at_most`.
double nice_length(double at_most) {
  const double power = std::pow(10.0, std::floor(std::log10(at_most)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * power <= at_most) return m * power;
  return power;
}

std::string elevation_text(double z, double interval) {
  const bool whole = std::fabs(interval - std::round(interval)) < 1e-9 && std::fabs(z - std::round(z)) < 1e-6;
  return whole ? fmt::format("{}", static_cast<long long>(std::llround(z))) : fmt::format("{:.1f}", z);
}

/// Approximate width of a label in digit heights (the stroke font is 0.6 wide per character).
double label_width(const std::string& text, double size) {
  return 0.62 * size * static_cast<double>(text.size());
}

/// A point well inside the ring (the best of its centroid and a 12 x 12 grid over its bounds,
/// by distance to the boundary): the centroid of a C-shaped summit lies outside it.
Point inner_point(const Ring& ring) {
  const Box box = bounds(ring);
  Point best = centroid(ring);
  double best_distance = contains(ring, best) ? distance_to_ring(ring, best) : -1.0;
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i) {
      const Point p{box.min_x + (i + 0.5) / 12.0 * box.width(), box.min_y + (j + 0.5) / 12.0 * box.height()};
      if (!contains(ring, p)) continue;
      const double d = distance_to_ring(ring, p);
      if (d > best_distance) best_distance = d, best = p;
    }
  return best;
}

}  // namespace

bool is_index_level(int level, double z0_m, double interval_m, int index_every) {
  const double k0 = z0_m / interval_m;
  const long long base = std::fabs(k0 - std::round(k0)) < 1e-6 ? std::llround(k0) : 0;
  const long long k = base + level;
  return ((k % index_every) + index_every) % index_every == 0;
}

MapDrawing layout_contour_map(const ContourTree& tree, const MapStyle& style) {
  MapDrawing map;
  Box box;
  for (const ContourNode& node : tree.nodes)
    for (const Point& p : node.ring) box.add(p);
  if (box.empty()) box.add({0, 0}), box.add({1, 1});
  // Fit the width; a tall map is limited to twice the width.
  const double margin_px = 0.06 * style.width_px;
  const double usable = style.width_px - 2.0 * margin_px;
  const double scale = std::min(usable / std::max(box.width(), 1e-9), 2.0 * usable / std::max(box.height(), 1e-9));  // px per m
  map.width_px = style.width_px;
  map.height_px = static_cast<int>(std::ceil(box.height() * scale + 2.0 * margin_px)) + 30;
  map.background = style.paper;
  const double ox = 0.5 * (map.width_px - box.width() * scale), oy = margin_px;
  auto to_px = [&](Point p) { return Point{ox + (p.x - box.min_x) * scale, oy + (box.max_y - p.y) * scale}; };

  const double z0 = tree.seed_elevation(), interval = tree.interval();

  // Ordinary contours first, index contours over them.
  std::vector<const ContourNode*> index_nodes;
  for (int pass = 0; pass < 2; ++pass)
    for (const ContourNode& node : tree.nodes) {
      // A crater's levels descend: their index follows their elevation, not their nesting.
      const int id = static_cast<int>(&node - tree.nodes.data());
      const int level = tree.descends(id) ? static_cast<int>(std::lround((node.elevation_m - z0) / interval)) : node.level;
      const bool index = is_index_level(level, z0, interval, std::max(1, style.index_every));
      if (index != (pass == 1)) continue;
      MapStroke stroke{{}, true, index ? style.index_line_px : style.line_px, style.contour};
      stroke.points.reserve(node.ring.size());
      for (const Point& p : node.ring) stroke.points.push_back(to_px(p));
      map.items.emplace_back(std::move(stroke));
      if (index) index_nodes.push_back(&node);
    }

  // Summits: a small triangle inside each summit contour.
  if (style.summits)
    for (int s : tree.summits()) {
      const ContourNode& node = tree.nodes[static_cast<std::size_t>(s)];
      if (node.level < 0) continue;
      const Point c = to_px(inner_point(node.ring));
      const double r = 0.35 * style.label_px;
      map.items.emplace_back(MapFill{{{c.x, c.y - r}, {c.x + 0.87 * r, c.y + 0.5 * r}, {c.x - 0.87 * r, c.y + 0.5 * r}}, style.ink});
    }

  // Labels on index contours, along the line where it runs most nearly east-west, reading uphill.
  if (style.labels)
    for (const ContourNode* node : index_nodes) {
      const std::string text = elevation_text(node->elevation_m, interval);
      const double width = label_width(text, style.label_px);
      const Ring& ring = node->ring;
      if (perimeter(ring) * scale < 6.0 * width) continue;
      std::size_t best = 0;
      double best_score = -1.0;
      const std::size_t n = ring.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Point a = to_px(ring[i]), b = to_px(ring[(i + 1) % n]);
        const Point d = b - a;
        const double l = length(d);
        if (l <= 0.0) continue;
        // Prefer flat, long-enough segments in the lower half of the map, away from its edges.
        const double flat = std::fabs(d.x) / l;
        const double south = a.y / map.height_px;
        const double score = flat * (0.5 + 0.5 * south) * std::min(1.0, l / width + 0.5);
        if (score > best_score) best_score = score, best = i;
      }
      const Point a = to_px(ring[best]), b = to_px(ring[(best + 1) % n]);
      double angle = std::atan2(b.y - a.y, b.x - a.x) * 180.0 / std::numbers::pi;
      if (angle > 90.0) angle -= 180.0;
      if (angle < -90.0) angle += 180.0;
      map.items.emplace_back(MapLabel{0.5 * (a + b), angle, style.label_px, text, style.contour, style.paper});
    }

  // Scale bar, bottom left: a nice length about a fifth of the map, in four alternating blocks.
  if (style.scale_bar) {
    const double metres = nice_length(0.22 * map.width_px / scale);
    const double length_px = metres * scale;
    const double x0 = 0.05 * map.width_px, y0 = map.height_px - 22.0, h = 6.0;
    for (int k = 0; k < 4; ++k) {
      const double xa = x0 + length_px * k / 4, xb = x0 + length_px * (k + 1) / 4;
      const std::vector<Point> block{{xa, y0}, {xb, y0}, {xb, y0 + h}, {xa, y0 + h}};
      map.items.emplace_back(MapFill{block, k % 2 == 0 ? style.ink : style.paper});
    }
    map.items.emplace_back(MapStroke{{{x0, y0}, {x0 + length_px, y0}, {x0 + length_px, y0 + h}, {x0, y0 + h}}, true, 1.0, style.ink});
    const std::string unit = metres >= 1000.0 ? fmt::format("{} km", metres / 1000.0) : fmt::format("{} m", metres);
    map.items.emplace_back(MapLabel{{x0, y0 - 9.0}, 0.0, 11.0, "0", style.ink, style.paper});
    map.items.emplace_back(MapLabel{{x0 + length_px, y0 - 9.0}, 0.0, 11.0, unit, style.ink, style.paper});
  }
  if (style.north_arrow) {
    const double x = map.width_px - 0.05 * map.width_px, y = 18.0;
    map.items.emplace_back(MapFill{{{x, y}, {x + 7.0, y + 22.0}, {x, y + 17.0}, {x - 7.0, y + 22.0}}, style.ink});
    map.items.emplace_back(MapLabel{{x, y + 34.0}, 0.0, 12.0, "N", style.ink, style.paper});
  }
  return map;
}

}  // namespace sansui::contour

#include "contour/geometry.hpp"

#include <algorithm>

namespace sansui::contour {

double signed_area(const Ring& ring) {
  // Relative to the first vertex, so far-from-origin rings keep their precision.
  if (ring.size() < 3) return 0.0;
  const Point o = ring[0];
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) twice += cross(ring[i] - o, ring[i + 1] - o);
  return 0.5 * twice;
}

double perimeter(const Ring& ring) {
  double total = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) total += distance(ring[i], ring[(i + 1) % n]);
  return total;
}

double mean_segment_length(const Ring& ring) {
  return ring.empty() ? 0.0 : perimeter(ring) / static_cast<double>(ring.size());
}

Box bounds(const Ring& ring) {
  Box box;
  for (const Point& p : ring) box.add(p);
  return box;
}

Box bounds(const std::vector<Ring>& rings) {
  Box box;
  for (const Ring& ring : rings)
    for (const Point& p : ring) box.add(p);
  return box;
}

void make_counter_clockwise(Ring& ring) {
  if (signed_area(ring) < 0.0) std::reverse(ring.begin(), ring.end());
}

int winding_number(const Ring& ring, Point p) {
  // Sunday's crossing rule: upward edges with p on their left count +1, downward with p on
  // their right count -1; edges are half-open in y so vertices count once.
  int winding = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point a = ring[i], b = ring[(i + 1) % n];
    if (a.y <= p.y) {
      if (b.y > p.y && cross(b - a, p - a) > 0.0) ++winding;
    } else if (b.y <= p.y && cross(b - a, p - a) < 0.0) {
      --winding;
    }
  }
  return winding;
}

double distance_to_segment(Point p, Point a, Point b) {
  const Point ab = b - a;
  const double squared = dot(ab, ab);
  const double t = squared > 0.0 ? std::clamp(dot(p - a, ab) / squared, 0.0, 1.0) : 0.0;
  return distance(p, a + t * ab);
}

double distance_to_ring(const Ring& ring, Point p) {
  double best = INFINITY;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) best = std::min(best, distance_to_segment(p, ring[i], ring[(i + 1) % n]));
  return best;
}

void remove_duplicates(Ring& ring, double tolerance) {
  if (ring.empty()) return;
  Ring kept;
  kept.reserve(ring.size());
  for (const Point& p : ring)
    if (kept.empty() || distance(kept.back(), p) > tolerance) kept.push_back(p);
  while (kept.size() > 1 && distance(kept.back(), kept.front()) <= tolerance) kept.pop_back();
  ring = std::move(kept);
}

Point centroid(const Ring& ring) {
  const Point o = ring.empty() ? Point{} : ring[0];
  double twice_area = 0.0, cx = 0.0, cy = 0.0;
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
    const Point a = ring[i] - o, b = ring[i + 1] - o;
    const double c = cross(a, b);
    twice_area += c;
    cx += (a.x + b.x) * c;
    cy += (a.y + b.y) * c;
  }
  if (twice_area == 0.0) return o;
  return {o.x + cx / (3.0 * twice_area), o.y + cy / (3.0 * twice_area)};
}

}  // namespace sansui::contour

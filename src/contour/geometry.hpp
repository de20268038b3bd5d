// Plane geometry shared by the contour stages: points in metres (x east, y north), closed rings,
// areas, lengths, containment. A Ring is a closed polygon whose last vertex connects back to the
// first (the first vertex is not repeated). Counter-clockwise (positive area) encloses higher
// ground.
#pragma once

#include <cmath>
#include <vector>

#include "core/plane_point.hpp"

namespace sansui::contour {

using Point = PlanePoint;  // core/plane_point.hpp: plain data that io reads and writes
using Ring = PlaneRing;

inline double dot(Point a, Point b) {
  return a.x * b.x + a.y * b.y;
}
inline double cross(Point a, Point b) {
  return a.x * b.y - a.y * b.x;
}
inline double length(Point a) {
  return std::sqrt(dot(a, a));
}
inline double distance(Point a, Point b) {
  return length(b - a);
}
/// a turned a quarter counter-clockwise.
inline Point left_normal(Point a) {
  return {-a.y, a.x};
}

struct Box {
  double min_x = INFINITY, min_y = INFINITY, max_x = -INFINITY, max_y = -INFINITY;
  void add(Point p) {
    min_x = std::fmin(min_x, p.x), min_y = std::fmin(min_y, p.y);
    max_x = std::fmax(max_x, p.x), max_y = std::fmax(max_y, p.y);
  }
  bool empty() const { return !(min_x <= max_x); }
  double width() const { return max_x - min_x; }
  double height() const { return max_y - min_y; }
};

/// The shoelace area, positive for counter-clockwise rings. [Units: m^2]
double signed_area(const Ring& ring);
/// Length of the closed ring, including the closing segment. [Units: m]
double perimeter(const Ring& ring);
/// Mean length of the ring's segments. [Units: m]
double mean_segment_length(const Ring& ring);
Box bounds(const Ring& ring);
Box bounds(const std::vector<Ring>& rings);
/// Reverses the ring if it is clockwise.
void make_counter_clockwise(Ring& ring);
/// Winding number of the ring around p (p on the boundary: either side).
int winding_number(const Ring& ring, Point p);
inline bool contains(const Ring& ring, Point p) {
  return winding_number(ring, p) != 0;
}
/// Distance from p to the segment a-b. [Units: m]
double distance_to_segment(Point p, Point a, Point b);
/// Distance from p to the closest point of the ring's boundary. [Units: m]
double distance_to_ring(const Ring& ring, Point p);
/// Removes consecutive duplicates (closer than `tolerance`), including last == first.
void remove_duplicates(Ring& ring, double tolerance = 0.0);
/// Area-weighted centroid.
Point centroid(const Ring& ring);

}  // namespace sansui::contour

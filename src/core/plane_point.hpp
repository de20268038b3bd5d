// A point of a plane in metres (x east, y north), and a closed ring of them: the plain data that
// contour lines, seed outlines and map drawings share with the formats that read and write them.
#pragma once

#include <vector>

namespace sansui {

struct PlanePoint {
  double x = 0.0;  ///< east. [Units: m]
  double y = 0.0;  ///< north. [Units: m]

  friend PlanePoint operator+(PlanePoint a, PlanePoint b) { return {a.x + b.x, a.y + b.y}; }
  friend PlanePoint operator-(PlanePoint a, PlanePoint b) { return {a.x - b.x, a.y - b.y}; }
  friend PlanePoint operator*(double s, PlanePoint a) { return {s * a.x, s * a.y}; }
  friend bool operator==(const PlanePoint&, const PlanePoint&) = default;
};

/// A closed polygon: its last vertex connects back to the first (which is not repeated).
using PlaneRing = std::vector<PlanePoint>;

}  // namespace sansui

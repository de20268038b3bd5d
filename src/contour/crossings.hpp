// Where a closed polyline crosses itself or another: the segment pairs found through a uniform
// grid of buckets, so that n-vertex curves cost about O(n) rather than O(n^2).
#pragma once

#include <vector>

#include "contour/geometry.hpp"

namespace sansui::contour {

/// One crossing of segment a (ring[a] to ring[a+1]) with segment b, at parameters t_a, t_b in [0, 1).
struct Crossing {
  int segment_a = 0;
  int segment_b = 0;
  double t_a = 0.0;
  double t_b = 0.0;
  Point at;
};

/// Every crossing of the closed ring with itself (segment_a < segment_b, adjacent segments are
/// not compared), ordered by (segment_a, segment_b). Collinear overlaps are not reported.
std::vector<Crossing> self_crossings(const Ring& ring);

/// Crossings between two closed rings (segment_a in a, segment_b in b).
std::vector<Crossing> crossings_between(const Ring& a, const Ring& b);

}  // namespace sansui::contour

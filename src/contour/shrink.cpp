// Polygon shrinking (Misawa, Chiba, Saito 1987, Sec. 2): see shrink.hpp.
#include "contour/shrink.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "contour/clipping.hpp"

namespace sansui::contour {
namespace {

Point unit(Point v) {
  const double l = length(v);
  return l > 0.0 ? (1.0 / l) * v : Point{};
}

Point rotate(Point v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

/// Appends the join between offset ends a = v + d*n1 and b = v + d*n2 (a gap).
/// With a varying offset, d1 and d2 are the offsets of the two edges and d their mean.
void append_join(Ring& curve, Point v, Point n1, Point n2, Point u1, Point u2, const OffsetParams& params, double d1, double d2) {
  const double d = 0.5 * (d1 + d2);
  const Point a = v + d1 * n1, b = v + d2 * n2;
  const double cos_between = dot(n1, n2);
  // A reversal (180 degree turn): the offset lines are parallel, so no miter exists; cap it square.
  const bool reversal = 1.0 + cos_between < 1e-12;
  switch (params.join) {
    case Join::straight:
      curve.push_back(a);
      curve.push_back(b);
      return;
    case Join::extended:
      if (reversal) {
        curve.push_back(a + d * u1);
        curve.push_back(b - d * u2);
      } else {
        curve.push_back(v + (d / (1.0 + cos_between)) * (n1 + n2));
      }
      return;
    case Join::clipped: {
      curve.push_back(a);
      const Point bisector = reversal ? u1 : unit(n1 + n2);
      const double miter = reversal ? INFINITY : d / std::sqrt(0.5 * (1.0 + cos_between));
      curve.push_back(v + std::min(params.clip_factor * d, miter) * bisector);
      curve.push_back(b);
      return;
    }
    case Join::arc: {
      const double sweep = std::atan2(cross(n1, n2), cos_between);
      const double step = params.arc_step_deg * std::numbers::pi / 180.0;
      const int segments = std::max(1, static_cast<int>(std::ceil(std::fabs(sweep) / step - 1e-9)));
      curve.push_back(a);
      for (int k = 1; k < segments; ++k) {
        const double t = static_cast<double>(k) / segments;
        curve.push_back(v + ((1.0 - t) * d1 + t * d2) * rotate(n1, sweep * t));
      }
      curve.push_back(b);
      return;
    }
  }
}

/// Unsigned angle at b between the segments to a and to c. [Units: radians]
double corner_angle(Point a, Point b, Point c) {
  const Point u = a - b, w = c - b;
  return std::fabs(std::atan2(cross(u, w), dot(u, w)));
}

}  // namespace

std::optional<Join> join_from_name(std::string_view name) {
  if (name == "extended") return Join::extended;
  if (name == "straight") return Join::straight;
  if (name == "arc") return Join::arc;
  if (name == "clipped") return Join::clipped;
  return std::nullopt;
}

std::string_view name_of(Join join) {
  switch (join) {
    case Join::extended:
      return "extended";
    case Join::straight:
      return "straight";
    case Join::arc:
      return "arc";
    case Join::clipped:
      return "clipped";
  }
  return "?";
}

Ring raw_offset_curve(const Ring& input, const OffsetParams& params) {
  Ring ring = input;
  remove_duplicates(ring);
  const std::size_t n = ring.size();
  if (n < 3) return {};
  const double side = params.outward ? -1.0 : 1.0;
  const double d = params.distance_m;
  std::vector<Point> directions(n), normals(n);
  std::vector<double> offsets(n, d);
  for (std::size_t i = 0; i < n; ++i) {
    directions[i] = unit(ring[(i + 1) % n] - ring[i]);
    normals[i] = side * left_normal(directions[i]);
    if (params.edge_distance) offsets[i] = params.edge_distance(ring[i], ring[(i + 1) % n]);
  }
  Ring curve;
  curve.reserve(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    // Vertex i joins edge i-1 (ending at it) and edge i (starting at it).
    const std::size_t previous = (i + n - 1) % n;
    const Point v = ring[i];
    const Point u1 = directions[previous], u2 = directions[i];
    const Point n1 = normals[previous], n2 = normals[i];
    const double d1 = offsets[previous], d2 = offsets[i];
    const double turn = cross(u1, u2);
    const bool collinear = std::fabs(turn) < 1e-12 && dot(u1, u2) > 0.0;
    if (collinear) {
      if (d1 != d2) curve.push_back(v + d1 * n1);
      curve.push_back(v + d2 * n2);
    } else if (side * turn < 0.0 || (std::fabs(turn) < 1e-12)) {
      append_join(curve, v, n1, n2, u1, u2, params, d1, d2);  // the offset edges part: a gap
    } else {
      // The offset edges overlap: pass through the vertex, so the small loops this makes have
      // the winding number of their surroundings on both sides.
      curve.push_back(v + d1 * n1);
      curve.push_back(v);
      curve.push_back(v + d2 * n2);
    }
    // The rest of edge i is its end point, added by the next vertex's join.
  }
  return curve;
}

std::vector<Ring> offset_ring(const Ring& ring, const OffsetParams& params) {
  const Ring curve = raw_offset_curve(ring, params);
  if (curve.size() < 3) return {};
  return positive_region(curve, false);
}

Ring preclean(const Ring& input, const PrecleanParams& params) {
  Ring ring = input;
  remove_duplicates(ring, params.min_segment_m);
  const double min_angle = params.min_angle_deg * std::numbers::pi / 180.0;
  // Repeated passes: removing one vertex changes the angles of its neighbours.
  for (int pass = 0; pass < 8 && ring.size() > 3; ++pass) {
    Ring kept;
    kept.reserve(ring.size());
    const std::size_t n = ring.size();
    bool changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      const Point a = kept.empty() ? ring[(i + n - 1) % n] : kept.back();
      const Point c = ring[(i + 1) % n];
      const bool sharp = corner_angle(a, ring[i], c) < min_angle;
      if (sharp && (n - i - 1) + kept.size() >= 3) {
        changed = true;
        continue;
      }
      kept.push_back(ring[i]);
    }
    ring = std::move(kept);
    remove_duplicates(ring, params.min_segment_m);
    if (!changed) break;
  }
  return ring;
}

}  // namespace sansui::contour

// Checking a map sketch before it is triangulated (see sketch.hpp). Kept apart from the CGAL
// code so that the messages name features and map points, which CGAL's exceptions cannot.
#include "mesh/sketch.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "core/error.hpp"

namespace sansui::mesh {
namespace {

struct Segment {
  SketchPoint a, b;
  std::size_t feature;
  double min_east, max_east;
};

double orient(const SketchPoint& a, const SketchPoint& b, const SketchPoint& p) {
  return (b.east_m - a.east_m) * (p.north_m - a.north_m) - (b.north_m - a.north_m) * (p.east_m - a.east_m);
}

bool same_place(const SketchPoint& a, const SketchPoint& b) {
  return a.east_m == b.east_m && a.north_m == b.north_m;
}

std::string place_text(const SketchPoint& p) {
  return fmt::format("(east {}, north {})", p.east_m, p.north_m);
}

const std::string& label_of(const Sketch& sketch, std::size_t feature) {
  return sketch.features[feature].label;
}

/// p lies on segment ab (collinear and within its box), ends included.
bool on_segment(const SketchPoint& a, const SketchPoint& b, const SketchPoint& p) {
  return orient(a, b, p) == 0.0 && std::min(a.east_m, b.east_m) <= p.east_m && p.east_m <= std::max(a.east_m, b.east_m) &&
         std::min(a.north_m, b.north_m) <= p.north_m && p.north_m <= std::max(a.north_m, b.north_m);
}

/// Where segments s and t meet other than at a shared end, if they do.
std::optional<SketchPoint> bad_contact(const Segment& s, const Segment& t) {
  const int shared = int(same_place(s.a, t.a)) + int(same_place(s.a, t.b)) + int(same_place(s.b, t.a)) + int(same_place(s.b, t.b));
  if (shared == 2) return std::nullopt;  // the same segment drawn twice
  const double d1 = orient(t.a, t.b, s.a), d2 = orient(t.a, t.b, s.b);
  const double d3 = orient(s.a, s.b, t.a), d4 = orient(s.a, s.b, t.b);
  if (shared == 1) {
    // Touching at the shared end is fine; running back along each other is not.
    if (d1 != 0.0 || d2 != 0.0) return std::nullopt;
    const SketchPoint& common = same_place(s.a, t.a) || same_place(s.a, t.b) ? s.a : s.b;
    const SketchPoint& s_far = same_place(common, s.a) ? s.b : s.a;
    const SketchPoint& t_far = same_place(common, t.a) ? t.b : t.a;
    const double dot = (s_far.east_m - common.east_m) * (t_far.east_m - common.east_m) +
                       (s_far.north_m - common.north_m) * (t_far.north_m - common.north_m);
    if (dot > 0.0) return common;
    return std::nullopt;
  }
  if (d1 == 0.0 && d2 == 0.0) {  // on one line: do they overlap?
    for (const SketchPoint* p : {&s.a, &s.b})
      if (on_segment(t.a, t.b, *p)) return *p;
    for (const SketchPoint* p : {&t.a, &t.b})
      if (on_segment(s.a, s.b, *p)) return *p;
    return std::nullopt;
  }
  const bool straddle_t = (d1 <= 0.0 && d2 >= 0.0) || (d1 >= 0.0 && d2 <= 0.0);
  const bool straddle_s = (d3 <= 0.0 && d4 >= 0.0) || (d3 >= 0.0 && d4 <= 0.0);
  if (!straddle_t || !straddle_s) return std::nullopt;
  const double f = d1 / (d1 - d2);
  return SketchPoint{s.a.east_m + f * (s.b.east_m - s.a.east_m), s.a.north_m + f * (s.b.north_m - s.a.north_m), 0.0};
}

void check_points(const Sketch& sketch) {
  std::map<std::pair<double, double>, std::pair<double, std::size_t>> height_at;  // place -> height, feature
  for (std::size_t f = 0; f < sketch.features.size(); ++f) {
    const SketchFeature& feature = sketch.features[f];
    if (feature.points.empty()) fail("{} has no points", feature.label);
    for (std::size_t k = 0; k < feature.points.size(); ++k) {
      const SketchPoint& p = feature.points[k];
      if (!std::isfinite(p.east_m) || !std::isfinite(p.north_m) || !std::isfinite(p.height_m))
        fail("{} has a point that is not finite numbers: east {}, north {}, height {}", feature.label, p.east_m, p.north_m, p.height_m);
      if (k > 0 && same_place(p, feature.points[k - 1]))
        fail("{} has the point {} twice in a row: a line needs distinct consecutive points", feature.label, place_text(p));
      const auto [it, inserted] = height_at.try_emplace({p.east_m, p.north_m}, p.height_m, f);
      if (!inserted && it->second.first != p.height_m)
        fail("the map point {} has two heights: {} m in {} and {} m in {}", place_text(p), it->second.first,
             label_of(sketch, it->second.second), p.height_m, feature.label);
    }
  }
  if (height_at.size() < 3) fail("the sketch has {} distinct map points: a surface needs at least three", height_at.size());
}

void check_crossings(const Sketch& sketch) {
  std::vector<Segment> segments;
  std::vector<std::pair<SketchPoint, std::size_t>> spots;
  for (std::size_t f = 0; f < sketch.features.size(); ++f) {
    const auto& points = sketch.features[f].points;
    if (points.size() == 1) spots.emplace_back(points[0], f);
    for (std::size_t k = 1; k < points.size(); ++k)
      segments.push_back({points[k - 1], points[k], f, std::min(points[k - 1].east_m, points[k].east_m),
                          std::max(points[k - 1].east_m, points[k].east_m)});
  }
  // Sweep from west to east: only segments whose east ranges overlap can meet.
  std::sort(segments.begin(), segments.end(), [](const Segment& a, const Segment& b) { return a.min_east < b.min_east; });
  for (std::size_t i = 0; i < segments.size(); ++i)
    for (std::size_t j = i + 1; j < segments.size() && segments[j].min_east <= segments[i].max_east; ++j) {
      const Segment &s = segments[i], &t = segments[j];
      if (std::max(s.a.north_m, s.b.north_m) < std::min(t.a.north_m, t.b.north_m) ||
          std::max(t.a.north_m, t.b.north_m) < std::min(s.a.north_m, s.b.north_m))
        continue;
      if (const auto at = bad_contact(s, t)) {
        if (s.feature == t.feature)
          fail("{} crosses or runs back over itself at {}: lines must not cross themselves", label_of(sketch, s.feature), place_text(*at));
        fail("{} and {} cross or touch at {} away from a shared point: add that point to both, with one height",
             label_of(sketch, std::min(s.feature, t.feature)), label_of(sketch, std::max(s.feature, t.feature)), place_text(*at));
      }
    }
  for (const auto& [spot, f] : spots)
    for (const Segment& s : segments)
      if (!same_place(spot, s.a) && !same_place(spot, s.b) && on_segment(s.a, s.b, spot))
        fail("{} lies on {} between two of its points: make it a point of that line", label_of(sketch, f), label_of(sketch, s.feature));
}

/// The frame's margin against the sketch's size: a frame closer than 1 % of it leaves slivers
/// the refinement cannot end on, one beyond 100 times it leaves the sketch a speck in the mesh
/// (and its float32 positions).
void check_frame(const Sketch& sketch, const SketchParams& params) {
  if (params.frame_margin_m == 0.0) return;
  double west = INFINITY, east = -INFINITY, south = INFINITY, north = -INFINITY;
  for (const SketchFeature& feature : sketch.features)
    for (const SketchPoint& p : feature.points) {
      west = std::min(west, p.east_m), east = std::max(east, p.east_m);
      south = std::min(south, p.north_m), north = std::max(north, p.north_m);
    }
  const double size = std::max(east - west, north - south);
  const double low = min_frame_ratio * size, high = max_frame_ratio * size;
  if (!(params.frame_margin_m >= low && params.frame_margin_m <= high))
    fail(
        "sketch.frame {} m is not allowed for this sketch ({:g} m across): it must be 0 (no frame) or between {:g} and {:g} m ({:g} to "
        "{:g} "
        "times its size)",
        params.frame_margin_m, size, low, high, min_frame_ratio, max_frame_ratio);
}

}  // namespace

void check_sketch(const Sketch& sketch, const SketchParams& params) {
  params::validate(params);
  if (sketch.features.empty()) fail("the sketch has no lines or points");
  check_points(sketch);
  check_crossings(sketch);
  check_frame(sketch, params);
}

}  // namespace sansui::mesh

#include "contour/clipping.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <polyclipping/clipper.hpp>

namespace sansui::contour {
namespace {

namespace cl = ClipperLib;

cl::Path to_clipper(const Ring& ring) {
  cl::Path path;
  path.reserve(ring.size());
  for (const Point& p : ring)
    path.emplace_back(static_cast<cl::cInt>(std::llround(p.x * clipper_units_per_metre)),
                      static_cast<cl::cInt>(std::llround(p.y * clipper_units_per_metre)));
  return path;
}

cl::Paths to_clipper(const std::vector<Ring>& rings) {
  cl::Paths paths;
  paths.reserve(rings.size());
  for (const Ring& ring : rings) paths.push_back(to_clipper(ring));
  return paths;
}

Ring from_clipper(const cl::Path& path) {
  Ring ring;
  ring.reserve(path.size());
  constexpr double metres = 1.0 / clipper_units_per_metre;
  for (const cl::IntPoint& p : path) ring.push_back({static_cast<double>(p.X) * metres, static_cast<double>(p.Y) * metres});
  return ring;
}

/// Outer rings only (positive orientation), in Clipper's order.
std::vector<Ring> outer_rings(const cl::Paths& paths) {
  std::vector<Ring> rings;
  for (const cl::Path& path : paths)
    if (path.size() >= 3 && cl::Orientation(path)) rings.push_back(from_clipper(path));
  return rings;
}

/// True if some path visits one point twice (where a strictly simple result would split): a sort,
/// O(n log n), where Clipper's own strictly-simple pass compares every pair of points of a ring.
bool touches_itself(const cl::Paths& paths) {
  std::vector<std::pair<cl::cInt, cl::cInt>> points;
  for (const cl::Path& path : paths) {
    points.clear();
    points.reserve(path.size());
    for (const cl::IntPoint& p : path) points.emplace_back(p.X, p.Y);
    std::sort(points.begin(), points.end());
    if (std::adjacent_find(points.begin(), points.end()) != points.end()) return true;
  }
  return false;
}

std::vector<Ring> execute(cl::ClipType type, const cl::Paths& subject, const cl::Paths& clip, cl::PolyFillType fill,
                          bool strictly_simple = true) {
  auto run = [&](bool strictly) {
    cl::Clipper clipper;
    clipper.StrictlySimple(strictly);            // a ring that would touch itself becomes two rings
    clipper.PreserveCollinear(strictly_simple);  // as strictly simple runs do: both give the same points
    clipper.AddPaths(subject, cl::ptSubject, true);
    if (!clip.empty()) clipper.AddPaths(clip, cl::ptClip, true);
    cl::Paths solution;
    clipper.Execute(type, solution, fill, fill);
    return solution;
  };
  // Clipper's strictly simple pass is quadratic in the points of a ring: run without it, and again
  // with it only when the result touches itself (rare: then both runs give the same rings).
  cl::Paths solution = run(false);
  if (strictly_simple && touches_itself(solution)) solution = run(true);
  return outer_rings(solution);
}

}  // namespace

std::vector<Ring> positive_region(const Ring& curve, bool strictly_simple) {
  return execute(cl::ctUnion, {to_clipper(curve)}, {}, cl::pftPositive, strictly_simple);
}

std::vector<Ring> positive_region(const std::vector<Ring>& curves) {
  return execute(cl::ctUnion, to_clipper(curves), {}, cl::pftPositive);
}

std::vector<Ring> intersection(const std::vector<Ring>& a, const std::vector<Ring>& b) {
  if (a.empty() || b.empty()) return {};
  return execute(cl::ctIntersection, to_clipper(a), to_clipper(b), cl::pftNonZero);
}

std::vector<Ring> difference(const std::vector<Ring>& a, const std::vector<Ring>& b) {
  if (a.empty()) return {};
  return execute(cl::ctDifference, to_clipper(a), to_clipper(b), cl::pftNonZero);
}

double intersection_area(const Ring& a, const Ring& b) {
  cl::Clipper clipper;
  clipper.AddPath(to_clipper(a), cl::ptSubject, true);
  clipper.AddPath(to_clipper(b), cl::ptClip, true);
  cl::Paths solution;
  clipper.Execute(cl::ctIntersection, solution, cl::pftNonZero, cl::pftNonZero);
  double area = 0.0;
  for (const cl::Path& path : solution) area += cl::Area(path);
  return area / (clipper_units_per_metre * clipper_units_per_metre);
}

std::vector<Ring> inflate(const std::vector<Ring>& rings, double delta_m) {
  cl::ClipperOffset offset(2.0, 0.05 * clipper_units_per_metre);
  offset.AddPaths(to_clipper(rings), cl::jtRound, cl::etClosedPolygon);
  cl::Paths solution;
  offset.Execute(solution, delta_m * clipper_units_per_metre);
  return outer_rings(solution);
}

bool is_simple(const Ring& ring) {
  const cl::Path path = to_clipper(ring);
  cl::Paths simple;
  cl::SimplifyPolygon(path, simple, cl::pftNonZero);
  if (simple.size() != 1) return false;
  return std::fabs(cl::Area(simple[0]) - std::fabs(cl::Area(path))) <= 1e-9 * std::fabs(cl::Area(path)) + 1.0;
}

}  // namespace sansui::contour

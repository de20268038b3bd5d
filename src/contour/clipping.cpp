#include "contour/clipping.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <polyclipping/clipper.hpp>

#include "core/error.hpp"

namespace sansui::contour {
namespace {

namespace cl = ClipperLib;

/// Clipper refuses coordinates beyond +-(2^62 - 1) units by throwing its own exception (which
/// would reach the user as an internal error), and llround is undefined past 2^63: points are
/// checked here, whatever the caller checked (seeds are held to max_seed_coordinate_m).
constexpr double max_clipper_units = 4e18;

cl::Path to_clipper(const Ring& ring) {
  cl::Path path;
  path.reserve(ring.size());
  for (const Point& p : ring) {
    const double x = p.x * clipper_units_per_metre, y = p.y * clipper_units_per_metre;
    if (!(std::abs(x) <= max_clipper_units) || !(std::abs(y) <= max_clipper_units))
      fail("a contour point ({:.6g}, {:.6g}) m is outside the range polygon clipping works in (|x|, |y| <= {:g} m)", p.x, p.y,
           max_clipper_units / clipper_units_per_metre);
    path.emplace_back(static_cast<cl::cInt>(std::llround(x)), static_cast<cl::cInt>(std::llround(y)));
  }
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

/// A pair of indices i < j where the path visits one point twice, or {0, 0}: a sort, O(n log n).
std::pair<std::size_t, std::size_t> repeated_point(const cl::Path& path) {
  std::vector<std::size_t> order(path.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  auto key = [&](std::size_t i) { return std::pair(path[i].X, path[i].Y); };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) != key(b) ? key(a) < key(b) : a < b; });
  for (std::size_t k = 1; k < order.size(); ++k)
    if (key(order[k]) == key(order[k - 1])) return {order[k - 1], order[k]};
  return {0, 0};
}

/// The paths split where they touch themselves, so that none visits a point twice: the result
/// Clipper's StrictlySimple option gives, whose own pass compares every pair of points of a ring
/// (quadratic; it took two thirds of the time of large mountains). A path that pinches becomes two
/// (two outer rings, or an outer ring and a hole, which outer_rings drops).
cl::Paths split_where_touching(cl::Paths paths) {
  cl::Paths done;
  while (!paths.empty()) {
    cl::Path path = std::move(paths.back());
    paths.pop_back();
    const auto [i, j] = repeated_point(path);
    if (i == j) {
      if (cl::Area(path) != 0.0) done.push_back(std::move(path));  // a split can leave a flat spike
      continue;
    }
    cl::Path loop(path.begin() + static_cast<std::ptrdiff_t>(i), path.begin() + static_cast<std::ptrdiff_t>(j));
    cl::Path rest(path.begin() + static_cast<std::ptrdiff_t>(j), path.end());
    rest.insert(rest.end(), path.begin(), path.begin() + static_cast<std::ptrdiff_t>(i));
    for (cl::Path* piece : {&loop, &rest})
      if (piece->size() >= 3) paths.push_back(std::move(*piece));
  }
  std::reverse(done.begin(), done.end());
  return done;
}

std::vector<Ring> execute(cl::ClipType type, const cl::Paths& subject, const cl::Paths& clip, cl::PolyFillType fill,
                          bool strictly_simple = true) {
  cl::Clipper clipper;
  clipper.PreserveCollinear(strictly_simple);  // as Clipper's strictly simple runs do
  clipper.AddPaths(subject, cl::ptSubject, true);
  if (!clip.empty()) clipper.AddPaths(clip, cl::ptClip, true);
  cl::Paths solution;
  clipper.Execute(type, solution, fill, fill);
  // Strictly simple: a ring that would touch itself becomes two rings.
  if (strictly_simple) solution = split_where_touching(std::move(solution));
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

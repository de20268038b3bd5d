// Cols that dip between summits: see cols.hpp.
#include "contour/cols.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "contour/clipping.hpp"

namespace sansui::contour {
namespace {

/// One col: the line it is carved along (a chord of its lowest cut contour) and that contour.
struct Col {
  Point from, to;
  int lowest = -1;
  int lowest_level = 0;
};

Point closest_on_segment(Point p, Point a, Point b) {
  const Point ab = b - a;
  const double squared = dot(ab, ab);
  const double t = squared > 0.0 ? std::clamp(dot(p - a, ab) / squared, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

/// The closest points of two rings (a vertex of one to a segment of the other, both ways).
std::pair<Point, Point> closest_points(const Ring& a, const Ring& b) {
  double best = INFINITY;
  std::pair<Point, Point> out{a.front(), b.front()};
  const auto search = [&](const Ring& from, const Ring& to, bool swapped) {
    for (const Point& p : from)
      for (std::size_t i = 0, n = to.size(); i < n; ++i) {
        const Point q = closest_on_segment(p, to[i], to[(i + 1) % n]);
        const double d = distance(p, q);
        if (d < best) best = d, out = swapped ? std::pair{q, p} : std::pair{p, q};
      }
  };
  search(a, b, false);
  search(b, a, true);
  return out;
}

/// The parameters t < 0 < t' of the nearest crossings of the line m + t u with `ring` on either
/// side of m (m inside the ring), or nullopt.
std::optional<std::pair<double, double>> chord(const Ring& ring, Point m, Point u) {
  double below = -INFINITY, above = INFINITY;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point a = ring[i], b = ring[(i + 1) % n];
    const double sa = cross(u, a - m), sb = cross(u, b - m);
    if ((sa > 0.0) == (sb > 0.0) || sa == sb) continue;
    const Point hit = a + (sa / (sa - sb)) * (b - a);
    const double t = dot(hit - m, u);
    if (t < 0.0) below = std::max(below, t);
    if (t >= 0.0) above = std::min(above, t);
  }
  if (!std::isfinite(below) || !std::isfinite(above)) return std::nullopt;
  return std::pair{below, above};
}

/// A counter-clockwise polygon holding every point within `radius` of the segment [a, b]: its
/// end caps' vertices lie at radius / cos(pi / 2n), so its edges stay outside the true capsule
/// (and within 0.2 % of the radius of it).
Ring capsule(Point a, Point b, double radius) {
  constexpr int per_end = 24;
  const double r = radius / std::cos(std::numbers::pi / (2.0 * per_end));
  const double angle = std::atan2(b.y - a.y, b.x - a.x);
  Ring ring;
  for (int end = 0; end < 2; ++end) {
    const Point centre = end == 0 ? b : a;
    const double start = angle - 0.5 * std::numbers::pi + end * std::numbers::pi;
    for (int k = 0; k <= per_end; ++k) {
      const double t = start + std::numbers::pi * k / per_end;
      ring.push_back({centre.x + r * std::cos(t), centre.y + r * std::sin(t)});
    }
  }
  return ring;
}

/// Distance between the segments [a, b] and [c, d] (0 when they cross).
double segment_distance(Point a, Point b, Point c, Point d) {
  const double s1 = cross(b - a, c - a), s2 = cross(b - a, d - a), s3 = cross(d - c, a - c), s4 = cross(d - c, b - c);
  if (((s1 > 0.0) != (s2 > 0.0)) && ((s3 > 0.0) != (s4 > 0.0))) return 0.0;
  return std::min({distance_to_segment(a, c, d), distance_to_segment(b, c, d), distance_to_segment(c, a, b), distance_to_segment(d, a, b)});
}

/// True if some point of `ring` (or of its inside) lies within `h` of the segment [a, b].
bool comes_near(const Ring& ring, const Box& box, Point a, Point b, double h) {
  if (std::max(a.x, b.x) + h < box.min_x || std::min(a.x, b.x) - h > box.max_x || std::max(a.y, b.y) + h < box.min_y ||
      std::min(a.y, b.y) - h > box.max_y)
    return false;
  if (contains(ring, a)) return true;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i)
    if (segment_distance(a, b, ring[i], ring[(i + 1) % n]) < h) return true;
  return false;
}

/// The col of the split at `node`, if it has one (see cols.hpp).
std::optional<Col> col_at(const ContourTree& tree, int node, int levels) {
  const ContourNode& split = tree.nodes[static_cast<std::size_t>(node)];
  if (split.level < 1 || tree.descends(node)) return std::nullopt;
  std::vector<int> rising;
  for (int c : split.children)
    if (!tree.descends(c)) rising.push_back(c);
  if (rising.size() < 2) return std::nullopt;
  std::stable_sort(rising.begin(), rising.end(), [&](int a, int b) {
    return signed_area(tree.nodes[static_cast<std::size_t>(a)].ring) > signed_area(tree.nodes[static_cast<std::size_t>(b)].ring);
  });
  const auto [a, b] =
      closest_points(tree.nodes[static_cast<std::size_t>(rising[0])].ring, tree.nodes[static_cast<std::size_t>(rising[1])].ring);
  if (!(distance(a, b) > 0.0)) return std::nullopt;
  const Point m = 0.5 * (a + b);
  const Point u = (1.0 / distance(a, b)) * left_normal(b - a);
  // Down from the split contour, at most `levels` contours, never the seed or below.
  int lowest = node;
  for (int k = 1; k < levels; ++k) {
    const int parent = tree.nodes[static_cast<std::size_t>(lowest)].parent;
    if (parent < 0 || tree.nodes[static_cast<std::size_t>(parent)].level < 1 || tree.descends(parent)) break;
    lowest = parent;
  }
  const Ring& ring = tree.nodes[static_cast<std::size_t>(lowest)].ring;
  if (!contains(ring, m)) return std::nullopt;
  const auto ends = chord(ring, m, u);
  if (!ends) return std::nullopt;
  return Col{m + ends->first * u, m + ends->second * u, lowest, tree.nodes[static_cast<std::size_t>(lowest)].level};
}

}  // namespace

void dip_cols(ContourTree& tree, const ColParams& params) {
  const std::size_t n = tree.nodes.size();
  std::vector<Col> cols;
  for (std::size_t i = 0; i < n; ++i)
    if (auto col = col_at(tree, static_cast<int>(i), params.levels)) cols.push_back(*col);
  if (cols.empty()) return;

  // The cols each contour lies under: those whose lowest cut contour encloses it (or is it).
  std::vector<std::vector<int>> under(n);
  for (std::size_t c = 0; c < cols.size(); ++c) {
    std::vector<int> stack{cols[c].lowest};
    while (!stack.empty()) {
      const int node = stack.back();
      stack.pop_back();
      under[static_cast<std::size_t>(node)].push_back(static_cast<int>(c));
      for (int child : tree.nodes[static_cast<std::size_t>(node)].children) stack.push_back(child);
    }
  }

  // Each contour less the notches of its cols at its level.
  std::vector<std::vector<Ring>> pieces(n);
  for (std::size_t i = 0; i < n; ++i) {
    const ContourNode& node = tree.nodes[i];
    std::vector<Ring> cutters;
    const Box box = bounds(node.ring);
    for (int c : under[i]) {
      const Col& col = cols[static_cast<std::size_t>(c)];
      const double half_width = 0.5 * params.offset_m * (node.level - col.lowest_level + 1);
      if (half_width > 0.0 && comes_near(node.ring, box, col.from, col.to, half_width))
        cutters.push_back(capsule(col.from, col.to, half_width));
    }
    if (cutters.empty()) {
      pieces[i].push_back(node.ring);
      continue;
    }
    for (Ring& r : difference({node.ring}, cutters))
      if (r.size() >= 3 && signed_area(r) >= params.min_area_m2) pieces[i].push_back(std::move(r));
  }

  // The new tree: every piece a node (in the old order, so parents still come before their
  // children inward), its parent the piece of the old parent that holds it.
  ContourTree out;
  std::vector<std::vector<int>> ids(n);
  for (std::size_t i = 0; i < n; ++i)
    for (Ring& r : pieces[i]) {
      ids[i].push_back(static_cast<int>(out.nodes.size()));
      out.nodes.push_back({std::move(r), tree.nodes[i].level, tree.nodes[i].elevation_m, -1, {}});
    }
  std::vector<char> orphan(out.nodes.size(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    const int parent = tree.nodes[i].parent;
    if (parent < 0) continue;
    for (int id : ids[i]) {
      const Point probe = out.nodes[static_cast<std::size_t>(id)].ring.front();
      int holder = -1;
      for (int candidate : ids[static_cast<std::size_t>(parent)])
        if (ids[static_cast<std::size_t>(parent)].size() == 1 || contains(out.nodes[static_cast<std::size_t>(candidate)].ring, probe)) {
          holder = candidate;
          break;
        }
      if (holder < 0) {
        orphan[static_cast<std::size_t>(id)] = 1;  // its parent's piece was dropped: it goes too
        continue;
      }
      out.nodes[static_cast<std::size_t>(id)].parent = holder;
      out.nodes[static_cast<std::size_t>(holder)].children.push_back(id);
    }
  }
  out.seed = ids[static_cast<std::size_t>(tree.seed)].front();
  if (std::find(orphan.begin(), orphan.end(), 1) != orphan.end()) {
    // Drop orphans and everything inside them, then renumber.
    std::vector<char> drop(out.nodes.size(), 0);
    std::vector<int> stack;
    for (std::size_t k = 0; k < orphan.size(); ++k)
      if (orphan[k] != 0) stack.push_back(static_cast<int>(k));
    while (!stack.empty()) {
      const int k = stack.back();
      stack.pop_back();
      drop[static_cast<std::size_t>(k)] = 1;
      for (int child : out.nodes[static_cast<std::size_t>(k)].children) stack.push_back(child);
    }
    std::vector<int> renumber(out.nodes.size(), -1);
    ContourTree kept;
    for (std::size_t k = 0; k < out.nodes.size(); ++k)
      if (drop[k] == 0) renumber[k] = static_cast<int>(kept.nodes.size()), kept.nodes.push_back(std::move(out.nodes[k]));
    for (ContourNode& node : kept.nodes) {
      node.parent = node.parent >= 0 ? renumber[static_cast<std::size_t>(node.parent)] : -1;
      std::erase_if(node.children, [&](int c) { return drop[static_cast<std::size_t>(c)] != 0; });
      for (int& c : node.children) c = renumber[static_cast<std::size_t>(c)];
    }
    kept.seed = renumber[static_cast<std::size_t>(out.seed)];
    out = std::move(kept);
  }
  tree = std::move(out);
}

}  // namespace sansui::contour

// Seed contour normalisation: see seed_input.hpp.
#include "contour/seed_input.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "contour/clipping.hpp"
#include "contour/crossings.hpp"
#include "core/error.hpp"

namespace sansui::contour {

SeedContour normalise_seed(Ring ring, bool closed, std::string_view source) {
  SeedContour seed;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point p = ring[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      fail("{}: vertex {} is ({}, {}): coordinates must be finite numbers", source, i, p.x, p.y);
    // Checked here, before any work: larger ones would overflow the clipping's integer lattice.
    if (std::abs(p.x) > max_seed_coordinate_m || std::abs(p.y) > max_seed_coordinate_m)
      fail("{}: vertex {} is ({:.6g}, {:.6g}): coordinates must lie within +-{:g} km of the origin", source, i, p.x, p.y,
           max_seed_coordinate_m / 1000.0);
  }
  if (ring.size() >= 2 && ring.front() == ring.back()) {
    closed = true;
  } else if (!closed && ring.size() >= 3) {
    const double gap = distance(ring.front(), ring.back());
    Ring open_line = ring;
    const double length = perimeter(open_line) - gap;
    if (gap > 0.05 * length)
      fail("{}: the seed contour is open: its ends are {:.6g} m apart ({:.1f}% of its length); close it", source, gap,
           100.0 * gap / length);
    seed.notes.push_back(fmt::format("{}: the line's ends were {:.3g} m apart; closed it", source, gap));
  }
  remove_duplicates(ring);
  Ring distinct = ring;
  std::sort(distinct.begin(), distinct.end(), [](Point a, Point b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if (distinct.size() < 3) fail("{}: the seed contour has {} distinct vertices: a contour needs at least 3", source, distinct.size());
  if (signed_area(ring) < 0.0) std::reverse(ring.begin(), ring.end());
  const auto crossings = self_crossings(ring);
  if (!crossings.empty()) {
    // Unambiguous if the region of positive winding is one piece and what it drops is small.
    const auto outline = positive_region(ring);
    Ring reversed(ring.rbegin(), ring.rend());
    double dropped = 0.0;
    for (const Ring& r : positive_region(reversed)) dropped += signed_area(r);
    const Point at = crossings.front().at;
    if (outline.size() != 1 || dropped > 0.05 * signed_area(outline[0]))
      fail("{}: the seed contour crosses itself at ({:.6g}, {:.6g}) and splits into {} parts: fix the seed", source, at.x, at.y,
           outline.size() + (dropped > 0.0 ? 1 : 0));
    seed.notes.push_back(fmt::format("{}: the seed crossed itself {} time(s), first at ({:.6g}, {:.6g}); repaired to its outline", source,
                                     crossings.size(), at.x, at.y));
    ring = outline[0];
  }
  const Box box = bounds(ring);
  const double area = signed_area(ring);
  if (!(area > 1e-12 * std::max(1.0, box.width() * box.height())) || area < 1e-6)
    fail("{}: the seed contour has zero area: its {} vertices lie on a line", source, ring.size());
  seed.ring = std::move(ring);
  return seed;
}

void check_seeds_apart(const std::vector<Ring>& seeds, std::string_view source) {
  std::vector<Box> boxes;
  boxes.reserve(seeds.size());
  for (const Ring& r : seeds) boxes.push_back(bounds(r));
  for (std::size_t i = 0; i < seeds.size(); ++i)
    for (std::size_t j = i + 1; j < seeds.size(); ++j) {
      const Box &a = boxes[i], &b = boxes[j];
      if (a.max_x < b.min_x || b.max_x < a.min_x || a.max_y < b.min_y || b.max_y < a.min_y) continue;
      const Ring &p = seeds[i], &q = seeds[j];
      if (!crossings_between(p, q).empty() || contains(p, q.front()) || contains(q, p.front()))
        fail(
            "{}: seed contours {} and {} of {} overlap (one crosses or holds the other): a file's polygons must be disjoint, one "
            "per mountain (a hole is not a seed)",
            source, i + 1, j + 1, seeds.size());
    }
}

}  // namespace sansui::contour

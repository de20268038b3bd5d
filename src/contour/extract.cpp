// Marching squares: see extract.hpp.
#include "contour/extract.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "contour/grid_frame.hpp"
#include "core/error.hpp"

namespace sansui::contour {
namespace {

class Marcher {
 public:
  Marcher(const Heightfield& heights, double level)
      : h_(heights), level_(level), frame_(GridFrame::of(heights)), pw_(heights.width() + 2), ph_(heights.height() + 2) {}

  std::vector<Ring> run() {
    const auto edges = static_cast<std::size_t>(2) * static_cast<std::size_t>(pw_) * static_cast<std::size_t>(ph_);
    next_.assign(edges, -1);
    for (int j = -1; j < h_.height(); ++j)
      for (int i = -1; i < h_.width(); ++i) march(i, j);
    std::vector<Ring> rings;
    for (std::size_t start = 0; start < edges; ++start) {
      if (next_[start] < 0) continue;
      Ring ring;
      std::int64_t e = static_cast<std::int64_t>(start);
      while (e >= 0 && next_[static_cast<std::size_t>(e)] >= 0) {
        ring.push_back(point_of(e));
        const std::int64_t following = next_[static_cast<std::size_t>(e)];
        next_[static_cast<std::size_t>(e)] = -1;
        e = following;
      }
      remove_duplicates(ring);
      if (ring.size() >= 3) rings.push_back(std::move(ring));
    }
    return rings;
  }

 private:
  double value(int i, int j) const {
    if (i < 0 || j < 0 || i >= h_.width() || j >= h_.height()) return -INFINITY;
    return h_(i, j);
  }
  bool inside(int i, int j) const { return value(i, j) > level_; }
  std::int64_t horizontal(int i, int j) const { return static_cast<std::int64_t>(j + 1) * pw_ + (i + 1); }
  std::int64_t vertical(int i, int j) const {
    return static_cast<std::int64_t>(pw_) * ph_ + static_cast<std::int64_t>(j + 1) * pw_ + (i + 1);
  }
  /// The two samples of an edge.
  void ends_of(std::int64_t e, int& i0, int& j0, int& i1, int& j1) const {
    const std::int64_t plane = static_cast<std::int64_t>(pw_) * ph_;
    const bool is_vertical = e >= plane;
    const std::int64_t local = is_vertical ? e - plane : e;
    i0 = static_cast<int>(local % pw_) - 1;
    j0 = static_cast<int>(local / pw_) - 1;
    i1 = is_vertical ? i0 : i0 + 1;
    j1 = is_vertical ? j0 + 1 : j0;
  }
  Point point_of(std::int64_t e) const {
    int i0, j0, i1, j1;
    ends_of(e, i0, j0, i1, j1);
    const double v0 = value(i0, j0), v1 = value(i1, j1);
    double t = 0.5;  // against the virtual border: half way
    if (std::isfinite(v0) && std::isfinite(v1) && v1 != v0) t = std::clamp((level_ - v0) / (v1 - v0), 0.0, 1.0);
    return frame_.at(i0 + t * (i1 - i0), j0 + t * (j1 - j0));
  }

  void march(int i, int j) {
    const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};  // NW NE SE SW
    int mask = 0;
    for (int k = 0; k < 4; ++k) mask |= inside(ci[k], cj[k]) ? 1 << k : 0;
    if (mask == 0 || mask == 15) return;
    const std::int64_t edge[4] = {horizontal(i, j), vertical(i + 1, j), horizontal(i, j + 1), vertical(i, j)};
    // Edge k joins corners (k, k+1 mod 4) for k = 0, 1; edge 2 joins corners 3, 2; edge 3 joins 0, 3.
    auto segment = [&](int a, int b) { add(edge[a], edge[b], a, b, ci, cj); };
    switch (mask) {
      case 1:
      case 14:
        segment(3, 0);
        break;
      case 2:
      case 13:
        segment(0, 1);
        break;
      case 4:
      case 11:
        segment(1, 2);
        break;
      case 8:
      case 7:
        segment(2, 3);
        break;
      case 3:
      case 12:
        segment(3, 1);
        break;
      case 6:
      case 9:
        segment(0, 2);
        break;
      case 5:
      case 10: {
        double centre = 0.0;
        for (int k = 0; k < 4; ++k) centre += value(ci[k], cj[k]);
        const bool centre_inside = 0.25 * centre > level_;
        // Cut off the two corners that are not joined through the centre.
        if ((mask == 5) == centre_inside) {
          segment(0, 1), segment(2, 3);
        } else {
          segment(3, 0), segment(1, 2);
        }
        break;
      }
      default:
        break;
    }
  }

  /// Records the segment between edges a and b of the cell, directed with the higher side on its left.
  void add(std::int64_t ea, std::int64_t eb, int a, int b, const int* ci, const int* cj) {
    static constexpr int shared[4][4] = {{-1, 1, -1, 0}, {1, -1, 2, -1}, {-1, 2, -1, 3}, {0, -1, 3, -1}};
    static constexpr int first_corner[4] = {0, 1, 3, 0};
    const int corner = shared[a][b] >= 0 ? shared[a][b] : first_corner[a];
    // Orientation from the edges' midpoints in index space (never degenerate, unlike the
    // interpolated points when a sample equals the level). Rows grow southward, so "left" in the
    // north-up plane is "right" here.
    static constexpr double mid_x[4] = {0.5, 1.0, 0.5, 0.0}, mid_y[4] = {0.0, 0.5, 1.0, 0.5};
    const Point p{mid_x[a], mid_y[a]}, q{mid_x[b], mid_y[b]};
    const Point c{static_cast<double>(ci[corner] - ci[0]), static_cast<double>(cj[corner] - cj[0])};
    const bool left = cross(q - p, c - p) < 0.0;
    if (left == inside(ci[corner], cj[corner])) {
      next_[static_cast<std::size_t>(ea)] = eb;
    } else {
      next_[static_cast<std::size_t>(eb)] = ea;
    }
  }

  const Heightfield& h_;
  double level_;
  GridFrame frame_;
  int pw_, ph_;
  std::vector<std::int64_t> next_;
};

}  // namespace

std::vector<Ring> extract_contours(const Heightfield& heights, double level) {
  if (heights.empty()) return {};
  return Marcher(heights, level).run();
}

ContourTree contours_of_dem(const Heightfield& heights, const std::vector<double>& levels) {
  ContourTree tree;
  std::vector<int> previous;  // ids of the level below
  for (std::size_t k = 0; k < levels.size(); ++k) {
    std::vector<int> current;
    for (Ring& ring : extract_contours(heights, levels[k])) {
      if (signed_area(ring) <= 0.0) continue;
      int parent = -1;
      for (int candidate : previous) {
        const Ring& around = tree.nodes[static_cast<std::size_t>(candidate)].ring;
        if (contains(around, ring[0]) &&
            (parent < 0 || signed_area(around) < signed_area(tree.nodes[static_cast<std::size_t>(parent)].ring)))
          parent = candidate;
      }
      const int id = static_cast<int>(tree.nodes.size());
      tree.nodes.push_back({std::move(ring), static_cast<int>(k), levels[k], parent, {}});
      if (parent >= 0) tree.nodes[static_cast<std::size_t>(parent)].children.push_back(id);
      current.push_back(id);
    }
    previous = std::move(current);
  }
  return tree;
}

Ring pick_contour(const Heightfield& heights, double level, std::optional<Point> pick) {
  if (heights.empty()) fail("the DEM is empty");
  const auto [low, high] = std::minmax_element(heights.values().begin(), heights.values().end());
  if (!std::isfinite(level) || !(level >= *low && level < *high))
    fail("--level {} is outside the DEM's range: it must lie in [{}, {})", level, *low, *high);
  std::vector<Ring> rings = extract_contours(heights, level);
  std::erase_if(rings, [](const Ring& r) { return signed_area(r) <= 0.0; });
  if (rings.empty()) fail("no closed contour around higher ground at level {}", level);
  if (pick) {
    const Ring* best = nullptr;
    for (const Ring& r : rings)
      if (contains(r, *pick) && (best == nullptr || signed_area(r) < signed_area(*best))) best = &r;
    if (best == nullptr)
      fail("--pick {},{} lies outside every contour at level {} ({} contours there)", pick->x, pick->y, level, rings.size());
    return *best;
  }
  return *std::max_element(rings.begin(), rings.end(), [](const Ring& a, const Ring& b) { return signed_area(a) < signed_area(b); });
}

}  // namespace sansui::contour

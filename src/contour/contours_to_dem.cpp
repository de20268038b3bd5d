// A DEM from a given contour map: see contours_to_dem.hpp.
#include "contour/contours_to_dem.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>

#include "contour/edt.hpp"
#include "contour/grid_frame.hpp"
#include "core/budget.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"

namespace sansui::contour {
namespace {

constexpr int rank_classes = 4;  // level ranks modulo 4: a region's two levels never share a class
constexpr int max_side = max_contour_dem_side;

struct Segment {
  Point a, b;   // grid coordinates: column, row
  int rank;     // index of the level in the sorted distinct levels
  int feature;  // line index, or lines + spot index
  bool spot;
};

/// Per region: the lowest and highest level rank on its border, from lines and from spots.
struct Region {
  int lo_line = INT_MAX, hi_line = -1, lo_spot = INT_MAX, hi_spot = -1;
  int lo() const { return std::min(lo_line, lo_spot); }
  int hi() const { return std::max(hi_line, hi_spot); }
  bool bracketed() const { return hi() >= 0; }
  double spacing_sum = 0.0;  // sum of d_lo + d_hi over its cells (two-level regions)
  double widest = 0.0;       // largest d_lo (one-level regions)
  long long cells = 0;
  double slope = 0.0;  // metres per cell
  int direction = 1;   // one-level regions: +1 dome, -1 bowl
};

void check_finite(double v, const char* what, std::size_t index) {
  if (!std::isfinite(v)) fail("{} {} has a non-finite value ({}): every coordinate and elevation must be a number", what, index, v);
}

}  // namespace

ContourMapGrid contour_map_grid(const ContourMap& map, int samples, double cell_m) {
  Box box;
  for (const ContourLine& line : map.lines)
    for (const Point& p : line.points) box.add(p);
  for (const SpotHeight& s : map.spots) box.add(s.at);
  if (box.empty()) fail("the contour map has no lines: nothing to interpolate");
  const double side = std::max(box.width(), box.height());
  if (!(side > 0.0)) fail("the contour map's extent is a single point: give lines that span an area");
  if (!(cell_m > 0.0)) {
    if (samples < 2 || samples > max_side) fail("size {} is not allowed: give 2..{} samples", samples, max_side);
    cell_m = side / (samples - 1);
  }
  ContourMapGrid grid;
  grid.cell_m = cell_m;
  const double w = std::ceil(box.width() / cell_m - 1e-9) + 1.0, h = std::ceil(box.height() / cell_m - 1e-9) + 1.0;
  if (w > max_side || h > max_side)
    fail("cell {} m makes a {:.0f} x {:.0f} grid over the contours: at most {} samples a side; give a larger cell", cell_m, w, h, max_side);
  grid.width = std::max(2, static_cast<int>(w));
  grid.height = std::max(2, static_cast<int>(h));
  grid.origin_x_m = box.min_x;
  grid.origin_y_m = -box.max_y;  // row 0 is the northern edge
  return grid;
}

budget::Cost contour_map_dem_cost(const ContourMapGrid& grid) {
  const double cells = static_cast<double>(grid.width) * static_cast<double>(grid.height);
  budget::Cost cost;
  // Bytes a cell: the nearest segment's distance and owner (8), the regions (4), the two
  // distances (8), the classes and sources (2), the feature transform's row table (2), the DEM (4).
  cost.bytes = 28.0 * cells;
  cost.seconds = 0.3e-6 * cells;
  cost.what = fmt::format("the DEM of {} x {} cells from the contour map (its working arrays)", grid.width, grid.height);
  cost.smaller = "give a smaller dem size or a larger cell";
  return cost;
}

namespace {

void check_map_and_grid(const ContourMap& map, const ContourMapGrid& grid) {
  if (map.lines.empty() && map.spots.empty()) fail("the contour map has no lines: nothing to interpolate");
  if (grid.width < 2 || grid.height < 2 || grid.width > max_side || grid.height > max_side)
    fail("grid {} x {} is not allowed: 2..{} samples a side", grid.width, grid.height, max_side);
  if (!(grid.cell_m > 0.0) || !std::isfinite(grid.cell_m)) fail("cell {} m is not allowed: it must be > 0", grid.cell_m);
}

/// The distinct levels of the map (lines and spots), lowest first, and the typical interval
/// between them.
struct Levels {
  std::vector<double> values;
  double interval = 0.0;  // the median step between levels (for domes beyond the highest level)

  int count() const { return static_cast<int>(values.size()); }
  double at(int rank) const { return values[static_cast<std::size_t>(rank)]; }
  int rank_of(double z) const { return static_cast<int>(std::lower_bound(values.begin(), values.end(), z) - values.begin()); }
  /// The interval to the next level in `direction` (+1 up, -1 down), or the typical one beyond.
  double step_from(int rank, int direction) const {
    const int next = rank + direction;
    if (next >= 0 && next < count()) return std::abs(at(next) - at(rank));
    return interval;
  }
};

/// The map's levels; InputError for a non-finite value or a line of fewer than two points.
Levels levels_of(const ContourMap& map) {
  Levels levels;
  std::vector<double>& values = levels.values;
  for (std::size_t i = 0; i < map.lines.size(); ++i) {
    const ContourLine& line = map.lines[i];
    check_finite(line.elevation_m, "line", i);
    if (line.points.size() < 2) fail("line {} has {} point(s): a contour line needs at least 2", i, line.points.size());
    for (const Point& p : line.points) check_finite(p.x, "line", i), check_finite(p.y, "line", i);
    values.push_back(line.elevation_m);
  }
  for (std::size_t i = 0; i < map.spots.size(); ++i) {
    check_finite(map.spots[i].elevation_m, "spot height", i);
    check_finite(map.spots[i].at.x, "spot height", i), check_finite(map.spots[i].at.y, "spot height", i);
    values.push_back(map.spots[i].elevation_m);
  }
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::vector<double> steps;
  for (std::size_t i = 1; i < values.size(); ++i) steps.push_back(values[i] - values[i - 1]);
  std::sort(steps.begin(), steps.end());
  levels.interval = steps.empty() ? 0.0 : steps[steps.size() / 2];
  return levels;
}

/// The lines' segments and the spots (as segments of one point) in grid coordinates, in the
/// map's order: lines first, then spots.
std::vector<Segment> segments_in_grid(const ContourMap& map, const Levels& levels, const GridFrame& frame) {
  std::vector<Segment> segments;
  std::size_t vertices = map.spots.size();
  for (const ContourLine& line : map.lines) vertices += line.points.size();
  segments.reserve(vertices);
  const auto to_grid = [&](Point p) { return Point{frame.column(p.x), frame.row(p.y)}; };
  for (std::size_t i = 0; i < map.lines.size(); ++i) {
    const ContourLine& line = map.lines[i];
    const int rank = levels.rank_of(line.elevation_m);
    const std::size_t n = line.points.size();
    const std::size_t count = line.closed && line.points.front() != line.points.back() ? n : n - 1;
    for (std::size_t k = 0; k < count; ++k)
      segments.push_back({to_grid(line.points[k]), to_grid(line.points[(k + 1) % n]), rank, static_cast<int>(i), false});
  }
  for (std::size_t i = 0; i < map.spots.size(); ++i) {
    const Point p = to_grid(map.spots[i].at);
    segments.push_back({p, p, levels.rank_of(map.spots[i].elevation_m), static_cast<int>(map.lines.size() + i), true});
  }
  return segments;
}

/// The drawn lines: per cell, its nearest segment (-1 where no line passes) and the distance to it.
struct DrawnLines {
  Grid<float> nearest;
  Grid<std::int32_t> owner;
};

/// Step 1: every cell within half a cell of a segment's samples keeps its nearest segment (in
/// order, so the first of equals wins). Bands of rows are drawn in parallel, each by the
/// segments that reach it, in their order: the same with any number of threads.
DrawnLines draw_lines(const std::vector<Segment>& segments, int w, int h) {
  DrawnLines drawn{Grid<float>(w, h, INFINITY), Grid<std::int32_t>(w, h, -1)};
  Grid<float>& nearest = drawn.nearest;
  Grid<std::int32_t>& owner = drawn.owner;
  constexpr int band_rows = 32;
  const int bands = (h + band_rows - 1) / band_rows;
  std::vector<std::vector<std::int32_t>> in_band(static_cast<std::size_t>(bands));
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const Segment& seg = segments[s];
    const double low = std::round(std::min(seg.a.y, seg.b.y)), high = std::round(std::max(seg.a.y, seg.b.y));
    if (high < 0 || low >= h) continue;
    const int first = static_cast<int>(std::max(0.0, low)) / band_rows, last = static_cast<int>(std::min<double>(h - 1, high)) / band_rows;
    for (int b = first; b <= last; ++b) in_band[static_cast<std::size_t>(b)].push_back(static_cast<std::int32_t>(s));
  }
  parallel_for(0, bands, [&](int b) {
    const int row0 = b * band_rows, row1 = std::min(h, row0 + band_rows);
    for (const std::int32_t s : in_band[static_cast<std::size_t>(b)]) {
      const Segment& seg = segments[static_cast<std::size_t>(s)];
      const int n = std::max(1, static_cast<int>(std::ceil(2.0 * distance(seg.a, seg.b))));
      for (int k = 0; k <= n; ++k) {
        const Point p = seg.a + (static_cast<double>(k) / n) * (seg.b - seg.a);
        // The nearest cell centre: floor(x + 1/2) (inlined, unlike std::round) for x >= -1/2.
        if (p.x < -0.5 || p.y < row0 - 0.5) continue;
        const double ri = std::floor(p.x + 0.5), rj = std::floor(p.y + 0.5);
        if (ri >= w || rj < row0 || rj >= row1) continue;
        const int i = static_cast<int>(ri), j = static_cast<int>(rj);
        const auto d = static_cast<float>(distance_to_segment({ri, rj}, seg.a, seg.b));
        if (d < nearest(i, j)) nearest(i, j) = d, owner(i, j) = s;
      }
    }
  });
  return drawn;
}

/// The regions between the lines: per cell, its region (-1 on a line), the regions with their
/// brackets, and the (region, feature) pairs of the features on their borders, sorted, once each.
struct Regions {
  Grid<std::int32_t> of_cell;
  std::vector<Region> list;
  std::vector<std::pair<int, int>> borders;  // (region, feature)
};

/// Fills region `id` from cell (i0, j0) over the cells no line passes through (4-connected),
/// counting its cells and taking its bracket and border features from the lines around it.
void fill_region(int i0, int j0, Regions& regions, const Grid<std::int32_t>& owner, const std::vector<Segment>& segments,
                 std::vector<std::int32_t>& stack) {
  const int w = owner.width(), h = owner.height();
  Grid<std::int32_t>& region = regions.of_cell;
  const auto id = static_cast<std::int32_t>(regions.list.size());
  regions.list.emplace_back();
  Region& r = regions.list.back();
  region(i0, j0) = id;
  stack.push_back(j0 * w + i0);
  int last_feature = -1;  // neighbouring cells mostly border the same line: push it once
  while (!stack.empty()) {
    const int c = stack.back();
    stack.pop_back();
    const int i = c % w, j = c / w;
    ++r.cells;
    const int ni[4] = {i - 1, i + 1, i, i}, nj[4] = {j, j, j - 1, j + 1};
    for (int q = 0; q < 4; ++q) {
      if (ni[q] < 0 || nj[q] < 0 || ni[q] >= w || nj[q] >= h) continue;
      const int o = owner(ni[q], nj[q]);
      if (o >= 0) {
        const Segment& seg = segments[static_cast<std::size_t>(o)];
        if (seg.spot)
          r.lo_spot = std::min(r.lo_spot, seg.rank), r.hi_spot = std::max(r.hi_spot, seg.rank);
        else
          r.lo_line = std::min(r.lo_line, seg.rank), r.hi_line = std::max(r.hi_line, seg.rank);
        if (seg.feature != last_feature) regions.borders.emplace_back(id, seg.feature), last_feature = seg.feature;
      } else if (region(ni[q], nj[q]) < 0) {
        region(ni[q], nj[q]) = id;
        stack.push_back(nj[q] * w + ni[q]);
      }
    }
  }
}

/// Step 2: the 4-connected components of the cells no line passes through, in row order of
/// their first cell, with their brackets and the features on their borders.
Regions find_regions(const Grid<std::int32_t>& owner, const std::vector<Segment>& segments, const Context& context) {
  const int w = owner.width(), h = owner.height();
  Regions regions{Grid<std::int32_t>(w, h, -1), {}, {}};
  std::vector<std::int32_t> stack;
  for (int j0 = 0; j0 < h; ++j0)
    for (int i0 = 0; i0 < w; ++i0) {
      if (owner(i0, j0) >= 0 || regions.of_cell(i0, j0) >= 0) continue;
      fill_region(i0, j0, regions, owner, segments, stack);
      context.check_cancelled();
    }
  std::vector<std::pair<int, int>>& borders = regions.borders;
  std::sort(borders.begin(), borders.end());
  borders.erase(std::unique(borders.begin(), borders.end()), borders.end());
  return regions;
}

/// Per cell, the distance to its region's lower and upper level (0 where it has none).
struct BracketDistances {
  Grid<float> d_lo, d_hi;
};

/// Per cell, the class of the level rank of its line (rank % rank_classes), 0xFF off the lines;
/// `class_used[c]` is set for every class some line's cell has.
Grid<std::uint8_t> rank_class_of_cells(const Grid<std::int32_t>& owner, const std::vector<Segment>& segments,
                                       std::vector<char>& class_used) {
  auto cell_class = Grid<std::uint8_t>::uninitialized(owner.width(), owner.height());
  for (std::size_t k = 0; k < owner.size(); ++k) {
    const int o = owner.data()[k];
    const int c = o < 0 ? 0xFF : segments[static_cast<std::size_t>(o)].rank % rank_classes;
    cell_class.data()[k] = static_cast<std::uint8_t>(c);
    if (o >= 0) class_used[static_cast<std::size_t>(c)] = 1;
  }
  return cell_class;
}

/// Step 3: the distances to each region's lower and upper level, by one feature transform per
/// class of ranks: a region's two levels never share a class, so each cell's nearest line of
/// the class is its bracket's.
BracketDistances distances_to_brackets(const Grid<std::int32_t>& owner, const std::vector<Segment>& segments, const Regions& regions,
                                       const Context& context) {
  const int w = owner.width(), h = owner.height();
  BracketDistances distances{Grid<float>(w, h, 0.0f), Grid<float>(w, h, 0.0f)};
  std::vector<char> class_used(rank_classes, 0);
  const Grid<std::uint8_t> cell_class = rank_class_of_cells(owner, segments, class_used);
  auto is_source = Grid<std::uint8_t>::uninitialized(w, h);
  for (int m = 0; m < rank_classes; ++m) {
    context.check_cancelled();
    if (class_used[static_cast<std::size_t>(m)] == 0) continue;
    const auto mark = static_cast<std::uint8_t>(m);
    const std::uint8_t* from = cell_class.data();
    std::uint8_t* to = is_source.data();
    for (std::size_t k = 0, n = is_source.size(); k < n; ++k) to[k] = from[k] == mark ? 1 : 0;
    visit_nearest_sources(is_source, [&](int i, int j, int si, int sj) {
      const int r = regions.of_cell(i, j);
      if (r < 0 || si < 0) return;
      const Region& reg = regions.list[static_cast<std::size_t>(r)];
      if (!reg.bracketed()) return;
      const bool lower = reg.lo() % rank_classes == m, upper = reg.hi() != reg.lo() && reg.hi() % rank_classes == m;
      if (!lower && !upper) return;
      const Segment& seg = segments[static_cast<std::size_t>(owner(si, sj))];
      const auto d = static_cast<float>(distance_to_segment({static_cast<double>(i), static_cast<double>(j)}, seg.a, seg.b));
      (lower ? distances.d_lo : distances.d_hi)(i, j) = d;
    });
    context.report("contour-dem", 0.25 + 0.55 * (m + 1) / rank_classes);
  }
  return distances;
}

/// Step 4a: the mean contour spacing and slope of every two-level region and the widest
/// distance of every one-level one. Returns the mean slope of the two-level regions.
double measure_regions(std::vector<Region>& regions, const Grid<std::int32_t>& region, const BracketDistances& distances,
                       const Levels& levels) {
  const Grid<float>& d_lo = distances.d_lo;
  const Grid<float>& d_hi = distances.d_hi;
  for (int j = 0; j < region.height(); ++j)
    for (int i = 0; i < region.width(); ++i) {
      const int r = region(i, j);
      if (r < 0) continue;
      Region& reg = regions[static_cast<std::size_t>(r)];
      if (!reg.bracketed()) continue;
      if (reg.hi() != reg.lo())
        reg.spacing_sum += static_cast<double>(d_lo(i, j)) + d_hi(i, j);
      else
        reg.widest = std::max(reg.widest, static_cast<double>(d_lo(i, j)));
    }
  double slope_sum = 0.0;
  long long slope_count = 0;
  for (Region& reg : regions)
    if (reg.bracketed() && reg.hi() != reg.lo() && reg.spacing_sum > 0.0) {
      const double spacing = reg.spacing_sum / static_cast<double>(reg.cells);
      reg.slope = (levels.at(reg.hi()) - levels.at(reg.lo())) / std::max(spacing, 1.0);
      slope_sum += reg.slope, ++slope_count;
    }
  return slope_count > 0 ? slope_sum / static_cast<double>(slope_count) : 0.0;
}

/// Step 4b: whether each one-level region rises or falls (the two-level regions across its
/// features vote: one lower than its level says it rises), and how steeply it leaves its
/// contour (the mean slope of those regions; `mean_slope` when it has none).
void orient_one_level_regions(Regions& regions, std::size_t features, const Levels& levels, double mean_slope) {
  std::vector<Region>& list = regions.list;
  // regions bordering each feature
  std::vector<std::vector<int>> of_feature(features);
  for (const auto& [r, f] : regions.borders) of_feature[static_cast<std::size_t>(f)].push_back(r);
  std::vector<int> votes(list.size(), 0);
  std::vector<double> across_slope(list.size(), 0.0);
  std::vector<int> across_count(list.size(), 0);
  for (const auto& [r, f] : regions.borders) {
    const Region& reg = list[static_cast<std::size_t>(r)];
    if (!reg.bracketed() || reg.hi() != reg.lo()) continue;
    const int k = reg.lo();
    for (int other : of_feature[static_cast<std::size_t>(f)]) {
      if (other == r) continue;
      const Region& o = list[static_cast<std::size_t>(other)];
      if (!o.bracketed() || o.hi() == o.lo()) continue;
      if (o.lo() < k) ++votes[static_cast<std::size_t>(r)];
      if (o.hi() > k) --votes[static_cast<std::size_t>(r)];
      across_slope[static_cast<std::size_t>(r)] += o.slope, ++across_count[static_cast<std::size_t>(r)];
    }
  }
  for (std::size_t r = 0; r < list.size(); ++r) {
    Region& reg = list[r];
    if (!reg.bracketed() || reg.hi() != reg.lo()) continue;
    const int k = reg.lo();
    reg.direction = votes[r] >= 0 ? 1 : -1;
    if (votes[r] == 0 && k == levels.count() - 1 && k > 0) reg.direction = 1;  // the top level: a summit
    if (votes[r] == 0 && k == 0 && levels.count() > 1) reg.direction = -1;     // the bottom level: a bowl
    reg.slope = across_count[r] > 0 ? across_slope[r] / across_count[r] : mean_slope;
  }
}

/// Step 5a: the heights of the cells between the lines: interpolated between a two-level
/// region's levels, a dome or bowl in a one-level region, the lowest level in an unbracketed one.
void fill_region_heights(Heightfield& out, const Regions& regions, const BracketDistances& distances, const Levels& levels) {
  const int w = out.width(), h = out.height();
  const double bottom = levels.values.front();
  parallel_for_ranges<int>(0, h, 8, [&](int range_begin, int range_end) {
    for (int j = range_begin; j < range_end; ++j)
      for (int i = 0; i < w; ++i) {
        const int r = regions.of_cell(i, j);
        if (r < 0) continue;
        const Region& reg = regions.list[static_cast<std::size_t>(r)];
        double z = bottom;
        if (reg.bracketed() && reg.hi() != reg.lo()) {
          const double lo = distances.d_lo(i, j), hi = distances.d_hi(i, j);
          double t = lo + hi > 0.0 ? lo / (lo + hi) : 0.5;
          // Towards a spot height the ground levels off (a rounded summit or pit floor).
          if (reg.hi_spot > reg.hi_line && reg.hi_line >= 0) t = 2.0 * t - t * t;
          if (reg.lo_spot < reg.lo_line && reg.lo_spot >= 0 && reg.hi_line >= 0) t = t * t;
          z = levels.at(reg.lo()) + (levels.at(reg.hi()) - levels.at(reg.lo())) * t;
        } else if (reg.bracketed()) {
          const double wide = std::max(reg.widest, 1e-6);
          const double t = std::min(1.0, distances.d_lo(i, j) / wide);
          const double height = std::min(0.5 * reg.slope * wide, 0.9 * levels.step_from(reg.lo(), reg.direction));
          z = levels.at(reg.lo()) + reg.direction * height * (2.0 * t - t * t);
        }
        out(i, j) = static_cast<float>(z);
      }
  });
}

/// Step 5b: the cells lines pass through: the line's level plus the slope on their side of it
/// (from the neighbours on that side, already filled), kept between the neighbouring levels.
void fill_line_heights(Heightfield& out, const DrawnLines& drawn, const std::vector<Segment>& segments, const Grid<std::int32_t>& region,
                       const Levels& levels) {
  const int w = out.width(), h = out.height();
  parallel_for_ranges<int>(0, h, 8, [&](int range_begin, int range_end) {
    for (int j = range_begin; j < range_end; ++j)
      for (int i = 0; i < w; ++i) {
        const int o = drawn.owner(i, j);
        if (o < 0) continue;
        const Segment& seg = segments[static_cast<std::size_t>(o)];
        const double z0 = levels.at(seg.rank);
        const Point c{static_cast<double>(i), static_cast<double>(j)};
        const double dc = drawn.nearest(i, j);  // its distance to its own segment, kept when drawn
        const double side = cross(seg.b - seg.a, c - seg.a);
        double sum = 0.0;
        int count = 0;
        if (!seg.spot && dc > 1e-9 && std::abs(side) > 1e-12) {
          const int ni[4] = {i - 1, i + 1, i, i}, nj[4] = {j, j, j - 1, j + 1};
          for (int q = 0; q < 4; ++q) {
            if (ni[q] < 0 || nj[q] < 0 || ni[q] >= w || nj[q] >= h || region(ni[q], nj[q]) < 0) continue;
            const Point n{static_cast<double>(ni[q]), static_cast<double>(nj[q])};
            if ((cross(seg.b - seg.a, n - seg.a) > 0.0) != (side > 0.0)) continue;
            const double dn = distance_to_segment(n, seg.a, seg.b);
            if (dn <= dc) continue;
            sum += (out(ni[q], nj[q]) - z0) * dc / dn;
            ++count;
          }
        }
        double z = count > 0 ? z0 + sum / count : z0;
        const double below = seg.rank > 0 ? levels.at(seg.rank - 1) : z0 - levels.interval;
        const double above = seg.rank + 1 < levels.count() ? levels.at(seg.rank + 1) : z0 + levels.interval;
        z = std::clamp(z, below, above);
        out(i, j) = static_cast<float>(z);
      }
  });
}

}  // namespace

Heightfield contour_map_to_dem(const ContourMap& map, const ContourMapGrid& grid, const Context& context) {
  check_map_and_grid(map, grid);
  budget::check(contour_map_dem_cost(grid), true);  // under a minute at the largest grid: memory is the limit
  const int w = grid.width, h = grid.height;
  const GridFrame frame{grid.origin_x_m, grid.origin_y_m, grid.cell_m};
  const Levels levels = levels_of(map);
  const std::vector<Segment> segments = segments_in_grid(map, levels, frame);

  const DrawnLines drawn = draw_lines(segments, w, h);
  context.check_cancelled();
  context.report("contour-dem", 0.1);

  Regions regions = find_regions(drawn.owner, segments, context);
  context.report("contour-dem", 0.25);

  const BracketDistances distances = distances_to_brackets(drawn.owner, segments, regions, context);

  const double mean_slope = measure_regions(regions.list, regions.of_cell, distances, levels);
  orient_one_level_regions(regions, map.lines.size() + map.spots.size(), levels, mean_slope);
  context.report("contour-dem", 0.85);

  Heightfield out = Heightfield::uninitialized(w, h, grid.cell_m);
  out.origin_x_m = grid.origin_x_m;
  out.origin_y_m = grid.origin_y_m;
  fill_region_heights(out, regions, distances, levels);
  fill_line_heights(out, drawn, segments, regions.of_cell, levels);
  context.report("contour-dem", 1.0);
  return out;
}

}  // namespace sansui::contour

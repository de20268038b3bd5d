// Contours to DEM: see to_dem.hpp.
#include "contour/to_dem.hpp"

#include <algorithm>
#include <cmath>

#include "contour/edt.hpp"
#include "contour/grid_frame.hpp"
#include "contour/random_keys.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "terrain/midpoint.hpp"

namespace sansui::contour {
namespace {

constexpr int depth_classes = 8;  // depth classes for the distance transforms (see to_dem.hpp)

struct RowCrossing {
  double x;
  int node;
  bool entering;
};

std::vector<int> depths_of(const ContourTree& tree) {
  std::vector<int> depth(tree.nodes.size(), 0);
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) depth[i] = tree.depth(static_cast<int>(i));
  return depth;
}

/// Midpoint displacement over a w x h grid: the top-left corner of the smallest square of
/// 2^levels + 1 samples a side that covers it.
Heightfield midpoint_noise(const terrain::MidpointParams& noise_params, int w, int h) {
  const int side = std::max(w, h);
  int levels = 1;
  while ((1 << levels) + 1 < side) ++levels;
  return terrain::generate_midpoint(noise_params, terrain::WorldWindow{levels, 0, Rect{0, 0, w, h}});
}

/// Outside the outermost contour: base + relief * s(t) * n, n midpoint displacement over the
/// grid scaled to zero mean and unit deviation, s = 3t^2 - 2t^3 of t = distance to the foot /
/// blend width: equal to the base at the foot, with zero slope, so the DEM is continuous there.
void add_foothills(Heightfield& out, const Grid<std::int32_t>& labels, const Grid<float>& d_out, const ContourTree& tree,
                   const DemParams& params, double base) {
  const int w = out.width(), h = out.height();
  double top = base;
  Box box;
  for (const ContourNode& node : tree.nodes) {
    top = std::max(top, node.elevation_m);
    for (const Point& p : node.ring) box.add(p);
  }
  const double relief = params.foothill_relief_m.value_or(0.1 * (top - base));
  const double width = params.foothill_width_m.value_or(std::max(0.1 * std::max(box.width(), box.height()), params.cell_m));
  if (!(relief > 0.0)) return;
  terrain::MidpointParams noise_params;
  // The terrain's seed is a whole number below 2^63 (its table's range): the stream key's top bit
  // is dropped (with it kept, half of all --seed values were refused).
  noise_params.seed = rng::stream_key(params.seed, static_cast<std::uint64_t>(Stream::foothills)) & 0x7FFF'FFFF'FFFF'FFFFull;
  noise_params.hurst = params.foothill_hurst;
  noise_params.sigma_m = 1.0;
  const Heightfield noise = midpoint_noise(noise_params, w, h);
  double sum = 0.0, squares = 0.0;
  for (float v : noise.values()) sum += v, squares += static_cast<double>(v) * v;
  const double n = static_cast<double>(noise.size());
  const double mean = sum / n;
  const double deviation = std::sqrt(std::max(1e-12, squares / n - mean * mean));
  const double scale = relief / deviation;
  parallel_for_ranges<int>(0, h, 8, [&](int range_begin, int range_end) {
    for (int j = range_begin; j < range_end; ++j)
      for (int i = 0; i < w; ++i) {
        if (labels(i, j) >= 0) continue;
        const double t = std::min(1.0, d_out(i, j) * params.cell_m / width);
        out(i, j) = static_cast<float>(base + t * t * (3.0 - 2.0 * t) * scale * (noise(i, j) - mean));
      }
  });
}

}  // namespace

DemParams dem_frame_for(const ContourTree& tree, int samples, double margin_fraction) {
  Box box;
  for (const ContourNode& node : tree.nodes)
    for (const Point& p : node.ring) box.add(p);
  if (box.empty()) box.add({0, 0}), box.add({1, 1});
  const double side = std::max({box.width(), box.height(), 1e-6});
  const double span = side * (1.0 + 2.0 * margin_fraction);
  DemParams params;
  params.cell_m = span / std::max(1, samples - 1);
  params.width = std::max(2, static_cast<int>(std::ceil((box.width() + 2.0 * margin_fraction * side) / params.cell_m)) + 1);
  params.height = std::max(2, static_cast<int>(std::ceil((box.height() + 2.0 * margin_fraction * side) / params.cell_m)) + 1);
  params.width = std::min(params.width, samples);
  params.height = std::min(params.height, samples);
  const double cx = 0.5 * (box.min_x + box.max_x), cy = 0.5 * (box.min_y + box.max_y);
  params.origin_x_m = cx - 0.5 * (params.width - 1) * params.cell_m;
  params.origin_y_m = -(cy + 0.5 * (params.height - 1) * params.cell_m);  // row 0 is the northern edge
  return params;
}

Grid<std::int32_t> innermost_contour(const ContourTree& tree, const DemParams& params) {
  const GridFrame frame{params.origin_x_m, params.origin_y_m, params.cell_m};
  const int w = params.width, h = params.height;
  // Every contour edge adds its crossing with each row's centre line (half-open in y, so a
  // vertex on the line counts once). Nested contours never cross, so along a row, entering a
  // contour means its inside and leaving it means its parent's.
  std::vector<std::vector<RowCrossing>> rows(static_cast<std::size_t>(h));
  for (std::size_t id = 0; id < tree.nodes.size(); ++id) {
    const Ring& ring = tree.nodes[id].ring;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point a = ring[i], b = ring[(i + 1) % n];
      if (a.y == b.y) continue;
      const double low = std::min(a.y, b.y), high = std::max(a.y, b.y);
      const int first = std::max(0, static_cast<int>(std::floor(frame.row(high))));
      const int last = std::min(h - 1, static_cast<int>(std::ceil(frame.row(low))));
      for (int j = first; j <= last; ++j) {
        const double y = frame.north(j);
        if (!(low <= y && y < high)) continue;
        const double x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
        rows[static_cast<std::size_t>(j)].push_back({x, static_cast<int>(id), b.y < a.y});
      }
    }
  }
  auto labels = Grid<std::int32_t>::uninitialized(w, h, params.cell_m);
  parallel_for_ranges<int>(0, h, 8, [&](int range_begin, int range_end) {
    for (int j = range_begin; j < range_end; ++j) {
      auto& crossings = rows[static_cast<std::size_t>(j)];
      std::sort(crossings.begin(), crossings.end(),
                [](const RowCrossing& a, const RowCrossing& b) { return a.x != b.x ? a.x < b.x : a.node < b.node; });
      std::int32_t* row = &labels(0, j);
      int label = -1, i = 0;
      for (const RowCrossing& c : crossings) {
        const int end = std::clamp(static_cast<int>(std::ceil(frame.column(c.x))), 0, w);
        for (; i < end; ++i) row[i] = label;
        label = c.entering ? c.node : tree.nodes[static_cast<std::size_t>(c.node)].parent;
      }
      for (; i < w; ++i) row[i] = label;
    }
  });
  labels.origin_x_m = params.origin_x_m;
  labels.origin_y_m = params.origin_y_m;
  return labels;
}

budget::Cost dem_cost(const DemParams& params) {
  const double cells = static_cast<double>(params.width) * static_cast<double>(params.height);
  // Bytes a cell: the labels (4), depth classes (1), lower and upper distances (8), the feature
  // transform's nearest distance, owner, source flag and row table (11), the DEM and weights (8),
  // not all alive at once; then the foothills' distance and noise, the roughness' noise.
  double per_cell = 22.0;
  if (params.surround == Surround::foothills) per_cell += 4.0;
  if (params.roughness_m > 0.0) per_cell += 8.0;
  budget::Cost cost;
  cost.bytes = per_cell * cells;
  cost.seconds = 0.26e-6 * cells;
  cost.what = fmt::format("the DEM of {} x {} cells from contours (its working arrays)", params.width, params.height);
  cost.smaller = "give a smaller size or a larger cell";
  return cost;
}

namespace {

using SegmentList = std::vector<std::pair<Point, Point>>;  // segments in grid coordinates

/// Every contour's segments in grid coordinates, by the depth class of the contour.
std::vector<SegmentList> segments_by_depth_class(const ContourTree& tree, const std::vector<int>& depth, const GridFrame& frame) {
  std::vector<SegmentList> segments(depth_classes);
  for (std::size_t id = 0; id < tree.nodes.size(); ++id) {
    const Ring& ring = tree.nodes[id].ring;
    auto& list = segments[static_cast<std::size_t>(depth[id] % depth_classes)];
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point a = ring[i], b = ring[(i + 1) % n];
      list.push_back({{frame.column(a.x), frame.row(a.y)}, {frame.column(b.x), frame.row(b.y)}});
    }
  }
  return segments;
}

/// Per cell: the depth class of its innermost contour (bits 0-2), whether that contour has
/// children (bit 3); 0xFF outside every contour.
Grid<std::uint8_t> cell_classes(const Grid<std::int32_t>& labels, const ContourTree& tree, const std::vector<int>& depth) {
  const int w = labels.width(), h = labels.height();
  Grid<std::uint8_t> cell_class = Grid<std::uint8_t>::uninitialized(w, h);
  parallel_for_ranges<int>(0, h, 16, [&](int range_begin, int range_end) {
    for (int j = range_begin; j < range_end; ++j)
      for (int i = 0; i < w; ++i) {
        const int l = labels(i, j);
        cell_class(i, j) = l < 0 ? std::uint8_t{0xFF}
                                 : static_cast<std::uint8_t>(depth[static_cast<std::size_t>(l)] % depth_classes |
                                                             (tree.nodes[static_cast<std::size_t>(l)].children.empty() ? 0 : 8));
      }
  });
  return cell_class;
}

/// The source cells of one depth class's feature transform: the cells its segments pass
/// through, each holding its nearest segment (`owner`, the first of equals). `touched` lists the
/// cells set, so that the next class clears only those.
struct SourceCells {
  Grid<float> best;
  Grid<std::int32_t> owner;
  Grid<std::uint8_t> is_source;
  std::vector<std::size_t> touched;
};

void draw_sources(const SegmentList& list, SourceCells& sources) {
  Grid<float>& best = sources.best;
  Grid<std::int32_t>& owner = sources.owner;
  Grid<std::uint8_t>& is_source = sources.is_source;
  const int w = best.width(), h = best.height();
  for (std::size_t k : sources.touched) best.data()[k] = INFINITY, is_source.data()[k] = 0;
  sources.touched.clear();
  for (std::size_t s = 0; s < list.size(); ++s) {
    const auto [a, b] = list[s];
    const int steps = std::max(1, static_cast<int>(std::ceil(2.0 * distance(a, b))));
    for (int k = 0; k <= steps; ++k) {
      const Point p = a + (static_cast<double>(k) / steps) * (b - a);
      const int i = static_cast<int>(std::lround(p.x)), j = static_cast<int>(std::lround(p.y));
      if (i < 0 || j < 0 || i >= w || j >= h) continue;
      const auto d = static_cast<float>(distance_to_segment({static_cast<double>(i), static_cast<double>(j)}, a, b));
      if (d < best(i, j)) {
        if (is_source(i, j) == 0) sources.touched.push_back(static_cast<std::size_t>(j) * w + i);
        best(i, j) = d, owner(i, j) = static_cast<std::int32_t>(s), is_source(i, j) = 1;
      }
    }
  }
}

/// Per cell, the distances to its lower and upper contour, and with foothills, outside every
/// contour, the distance to the foot. [Units: cells]
struct ContourDistances {
  Grid<float> d_low, d_up, d_out;
};

/// The distances to the lower and upper contour of every cell, one depth class at a time: the
/// cells each contour segment passes through are the sources of a feature transform, and a
/// cell's distance is measured exactly to the segment held by its nearest source cell.
ContourDistances distances_to_contours(const std::vector<SegmentList>& segments, const Grid<std::uint8_t>& cell_class, bool foothills,
                                       const Context& context) {
  const int w = cell_class.width(), h = cell_class.height();
  ContourDistances distances{Grid<float>(w, h, 0.0f), Grid<float>(w, h, 0.0f), Grid<float>()};
  SourceCells sources{Grid<float>(w, h, INFINITY), Grid<std::int32_t>(w, h), Grid<std::uint8_t>(w, h, 0), {}};
  // Foothills: every outside cell's distance to the foot (the roots, all of depth class 1).
  if (foothills) distances.d_out = Grid<float>(w, h, 0.0f);
  for (int m = 0; m < depth_classes; ++m) {
    const auto& list = segments[static_cast<std::size_t>(m)];
    if (list.empty()) continue;
    context.check_cancelled();
    draw_sources(list, sources);
    const Grid<std::int32_t>& owner = sources.owner;
    visit_nearest_sources(sources.is_source, [&](int i, int j, int si, int sj) {
      const std::uint8_t c = cell_class(i, j);
      if (si < 0) return;
      if (c == 0xFF) {
        if (foothills && m == 1) {
          const auto [a, b] = list[static_cast<std::size_t>(owner(si, sj))];
          distances.d_out(i, j) = static_cast<float>(distance_to_segment({static_cast<double>(i), static_cast<double>(j)}, a, b));
        }
        return;
      }
      const int k = c & 7;
      const bool lower = k == m, upper = (c & 8) != 0 && (k + 1) % depth_classes == m;
      if (!lower && !upper) return;
      const auto [a, b] = list[static_cast<std::size_t>(owner(si, sj))];
      const auto d = static_cast<float>(distance_to_segment({static_cast<double>(i), static_cast<double>(j)}, a, b));
      (lower ? distances.d_low : distances.d_up)(i, j) = d;
    });
    context.report("dem", 0.1 + 0.7 * (m + 1) / depth_classes);
  }
  return distances;
}

/// The widest inner distance of every summit contour (0 for the others), for its cap.
std::vector<float> summit_widths(const ContourTree& tree, const Grid<std::int32_t>& labels, const Grid<float>& d_low) {
  std::vector<float> widest(tree.nodes.size(), 0.0f);
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const int l = labels.data()[k];
    if (l >= 0 && tree.nodes[static_cast<std::size_t>(l)].children.empty())
      widest[static_cast<std::size_t>(l)] = std::max(widest[static_cast<std::size_t>(l)], d_low.data()[k]);
  }
  return widest;
}

/// The level outside every contour: params.base_m, or the lowest root's.
double base_level(const ContourTree& tree, const DemParams& params) {
  double base = INFINITY;
  for (int root : tree.roots()) base = std::min(base, tree.nodes[static_cast<std::size_t>(root)].elevation_m);
  return params.base_m.value_or(base);
}

/// How far a summit rises above its contour: params.cap_m, or the first interval between a
/// contour and its child, or the offset between contours.
double cap_height(const ContourTree& tree, const DemParams& params) {
  double interval = 0.0;
  for (const ContourNode& node : tree.nodes)
    if (!node.children.empty()) {
      interval = tree.nodes[static_cast<std::size_t>(node.children[0])].elevation_m - node.elevation_m;
      break;
    }
  return params.cap_m.value_or(interval > 0.0 ? interval : params.offset_m);
}

/// The heights inside the contours: between a contour and its child by the distances to them,
/// a cap over a summit, flat in a depression; `base` outside. `weight` gets each cell's position
/// between its contours (0 on the lower), for the roughness.
void interpolate_heights(Heightfield& out, Grid<float>& weight, const Grid<std::int32_t>& labels, const ContourDistances& distances,
                         const ContourTree& tree, const DemParams& params, double base, double cap) {
  const int w = out.width(), h = out.height();
  const std::vector<float> widest = summit_widths(tree, labels, distances.d_low);
  parallel_for_ranges<int>(0, h, 8, [&](int range_begin, int range_end) {
    for (int j = range_begin; j < range_end; ++j)
      for (int i = 0; i < w; ++i) {
        const int l = labels(i, j);
        if (l < 0) {
          out(i, j) = static_cast<float>(base);
          continue;
        }
        const ContourNode& node = tree.nodes[static_cast<std::size_t>(l)];
        const double low = distances.d_low(i, j);
        double z;
        if (node.children.empty() && tree.descends(l)) {
          z = node.elevation_m;  // the flat floor of a depression
        } else if (node.children.empty()) {
          const double wide = widest[static_cast<std::size_t>(l)];
          const double t = wide > 0.0 ? std::min(1.0, low / wide) : 1.0;
          const double height = cap * std::min(1.0, wide * params.cell_m / (2.0 * params.offset_m));
          z = node.elevation_m + height * (2.0 * t - t * t);
          weight(i, j) = static_cast<float>(t);
        } else {
          const double up = distances.d_up(i, j);
          const double upper = tree.nodes[static_cast<std::size_t>(node.children[0])].elevation_m;
          const double t = low + up > 0.0 ? low / (low + up) : 0.5;
          z = node.elevation_m + (upper - node.elevation_m) * t;
          weight(i, j) = static_cast<float>(t);
        }
        out(i, j) = static_cast<float>(z);
      }
  });
}

/// Fig. 11: midpoint displacement on the surface, fading to zero on the contours (4 t (1-t))
/// and clamped between the cell's contours, so contours stay where they were generated.
void add_roughness(Heightfield& out, const Grid<float>& weight, const Grid<std::int32_t>& labels, const ContourTree& tree,
                   const DemParams& params, double cap) {
  const int w = out.width(), h = out.height();
  terrain::MidpointParams noise_params;
  noise_params.seed = params.seed;
  noise_params.hurst = params.roughness_hurst;
  noise_params.sigma_m = params.roughness_m;
  const Heightfield noise = midpoint_noise(noise_params, w, h);
  double mean = 0.0;
  for (float v : noise.values()) mean += v;
  mean /= static_cast<double>(noise.size());
  parallel_for_ranges<int>(0, h, 8, [&](int range_begin, int range_end) {
    for (int j = range_begin; j < range_end; ++j)
      for (int i = 0; i < w; ++i) {
        const int l = labels(i, j);
        if (l < 0) continue;
        const ContourNode& node = tree.nodes[static_cast<std::size_t>(l)];
        if (node.children.empty() && tree.descends(l)) continue;  // a depression's flat floor
        const double t = weight(i, j);
        const double z_node = node.elevation_m;
        const double z_next = node.children.empty() ? z_node + cap : tree.nodes[static_cast<std::size_t>(node.children[0])].elevation_m;
        const double lower = std::min(z_node, z_next), upper = std::max(z_node, z_next);
        const double z = out(i, j) + 4.0 * t * (1.0 - t) * (noise(i, j) - mean);
        // Strictly between, so the contours extracted from the DEM stay where they were.
        const double margin = 1e-4 * (upper - lower);
        out(i, j) = static_cast<float>(std::clamp(z, lower + margin, upper - margin));
      }
  });
}

}  // namespace

Heightfield contours_to_dem(const ContourTree& tree, const DemParams& params, const Context& context) {
  params.validate();
  if (tree.nodes.empty()) fail("no contours to rasterise");
  budget::check(dem_cost(params), true);  // 2 minutes at 32768^2 cells: memory, not time, is the limit
  const int w = params.width, h = params.height;
  const std::vector<int> depth = depths_of(tree);
  const Grid<std::int32_t> labels = innermost_contour(tree, params);
  context.report("dem", 0.1);

  const GridFrame frame{params.origin_x_m, params.origin_y_m, params.cell_m};
  const bool foothills = params.surround == Surround::foothills;
  const ContourDistances distances =
      distances_to_contours(segments_by_depth_class(tree, depth, frame), cell_classes(labels, tree, depth), foothills, context);

  const double base = base_level(tree, params);
  const double cap = cap_height(tree, params);
  Heightfield out = Heightfield::uninitialized(w, h, params.cell_m);
  out.origin_x_m = params.origin_x_m;
  out.origin_y_m = params.origin_y_m;
  Grid<float> weight(w, h, 0.0f);  // position between lower and upper contour, for roughness
  interpolate_heights(out, weight, labels, distances, tree, params, base, cap);
  context.report("dem", 0.9);

  if (params.roughness_m > 0.0) add_roughness(out, weight, labels, tree, params, cap);
  if (foothills) add_foothills(out, labels, distances.d_out, tree, params, base);
  context.report("dem", 1.0);
  return out;
}

}  // namespace sansui::contour

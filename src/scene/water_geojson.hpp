// Rivers and lakes as GeoJSON features (io/geojson_features.hpp): rivers as one LineString per
// reach (upstream to downstream) with its Strahler order, drainage area and discharge; lakes as
// one Polygon per lake (its outline traced between flooded and dry samples, islands as holes)
// with its water level, area and volume. Coordinates in metres of the heightfield's plane.
//
// The whole-world writers below and the tiled one (tiled_water.hpp) build their features with
// the same parts (river_feature, LakeShore), so that both give the same bytes.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "contour/grid_frame.hpp"
#include "core/grid.hpp"
#include "core/rect.hpp"
#include "io/geojson_features.hpp"
#include "water/priority_flood.hpp"
#include "water/rivers.hpp"

namespace sansui::scene {

/// The reaches of `rivers`, positioned by `grid` (the heightfield they were traced on).
std::string rivers_to_geojson(const water::RiverNetwork& rivers, const Heightfield& grid);

/// The lakes of `lakes`; `ground` gives the plane (cell size, origin).
std::string lakes_to_geojson(const water::LakeFill& lakes, const Heightfield& ground);

/// What a reach's feature says of it besides its line.
struct ReachProperties {
  int id = 0;  ///< the feature's number among the written reaches
  int strahler_order = 1;
  double area_m2 = 0.0;  ///< [Units: m^2]
  double discharge_m3_per_s = 0.0;
};
nlohmann::json reach_properties(const ReachProperties& reach);

/// One reach as a line: `cells` are world indices y * width + x, upstream first (two or more).
template <class Cell>
io::LineFeature river_feature(const std::vector<Cell>& cells, std::int64_t width, const contour::GridFrame& frame,
                              const ReachProperties& reach) {
  io::LineFeature feature;
  feature.line.reserve(cells.size());
  for (const Cell cell : cells) {
    const std::int64_t column = cell % width, row = cell / width;  // whole cells: the division is meant
    feature.line.push_back({frame.east(static_cast<double>(column)), frame.north(static_cast<double>(row))});
  }
  feature.properties = reach_properties(reach);
  return feature;
}

/// What a lake's features say of it.
struct LakeProperties {
  int id = 0;            ///< the lake's number among the kept lakes
  float level_m = 0.0f;  ///< [Units: m]
  std::int64_t cells = 0;
  double volume_m3 = 0.0;  ///< [Units: m^3]
};

/// Grows `box` (half-open; empty at first) to hold cell (x, y).
inline void add_to_box(Rect& box, int x, int y) {
  box = box.empty() ? Rect{x, y, x + 1, y + 1}
                    : Rect{std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x + 1), std::max(box.y1, y + 1)};
}

/// The shore of one lake, traced by marching squares on a mask of its cells (1 in, 0 out) at
/// one half: half a cell out from its cells. The mask covers the lake's bounding box and a ring
/// of dry cells, so that every ring closes inside it.
class LakeShore {
 public:
  /// `box`: the bounding box of the lake's cells, world cells (half-open).
  LakeShore(const Rect& box, const contour::GridFrame& frame);
  /// Marks world cell (x, y), inside the box, as the lake's.
  void add(int x, int y) { mask_(x - box_.x0 + 1, y - box_.y0 + 1) = 1.0f; }
  /// The lake as one feature: its polygons (one, or several where its cells touch only at
  /// corners), each with its islands as holes, and the whole lake's area and volume.
  io::PolygonFeature feature(const LakeProperties& lake) const;

 private:
  Rect box_;
  Heightfield mask_;
};

}  // namespace sansui::scene

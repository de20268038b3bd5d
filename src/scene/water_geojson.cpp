#include "scene/water_geojson.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "contour/extract.hpp"
#include "contour/geometry.hpp"
#include "contour/grid_frame.hpp"
#include "io/geojson_features.hpp"

namespace sansui::scene {

std::string rivers_to_geojson(const water::RiverNetwork& rivers, const Heightfield& grid) {
  const auto frame = contour::GridFrame::of(grid);
  std::vector<io::LineFeature> features;
  int id = 0;
  for (const water::River& river : rivers.rivers) {
    if (river.cells.size() < 2) continue;  // a line needs two positions
    io::LineFeature feature;
    for (const water::CellIndex cell : river.cells) {
      const int column = cell % grid.width(), row = cell / grid.width();  // whole cells: the division is meant
      feature.line.push_back({frame.east(column), frame.north(row)});
    }
    feature.properties = {{"id", id++},
                          {"strahler", river.strahler_order},
                          {"area_m2", std::round(river.area_m2)},
                          {"discharge_m3_s", std::round(river.discharge_m3_per_s * 1e4) / 1e4}};
    features.push_back(std::move(feature));
  }
  return io::lines_to_geojson(features, "rivers");
}

std::string lakes_to_geojson(const water::LakeFill& lakes, const Heightfield& ground) {
  const int width = ground.width(), height = ground.height();
  // Each lake's bounding box, so that its outline is traced on a small mask.
  struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
  };
  std::vector<Box> boxes(lakes.lakes.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (const std::int32_t label = lakes.lake(x, y); label > 0) {
        Box& b = boxes[static_cast<std::size_t>(label - 1)];
        b = {std::min(b.x0, x), std::min(b.y0, y), std::max(b.x1, x), std::max(b.y1, y)};
      }
  std::vector<io::PolygonFeature> features;
  const double cell_area = ground.cell_size_m * ground.cell_size_m;
  for (std::size_t k = 0; k < lakes.lakes.size(); ++k) {
    const Box& b = boxes[k];
    if (b.x1 < 0) continue;
    // Marching squares on the lake's mask (1 in, 0 out) at one half: its shore, half a cell out.
    Heightfield mask(b.x1 - b.x0 + 1, b.y1 - b.y0 + 1, 0.0f, ground.cell_size_m);
    mask.origin_x_m = ground.origin_x_m + b.x0 * ground.cell_size_m;
    mask.origin_y_m = ground.origin_y_m + b.y0 * ground.cell_size_m;
    const auto label = static_cast<std::int32_t>(k + 1);
    for (int y = b.y0; y <= b.y1; ++y)
      for (int x = b.x0; x <= b.x1; ++x) mask(x - b.x0, y - b.y0) = lakes.lake(x, y) == label ? 1.0f : 0.0f;
    std::vector<contour::Ring> rings = contour::extract_contours(mask, 0.5);
    // The shore first (the largest ring), then islands as holes.
    std::sort(rings.begin(), rings.end(), [](const contour::Ring& a, const contour::Ring& c) {
      return std::abs(contour::signed_area(a)) > std::abs(contour::signed_area(c));
    });
    io::PolygonFeature feature;
    for (const contour::Ring& ring : rings) {
      if (ring.size() < 3) continue;
      std::vector<io::Position> positions;
      for (const contour::Point& p : ring) positions.push_back({p.x, p.y});
      feature.rings.push_back(std::move(positions));
    }
    if (feature.rings.empty()) continue;
    const water::Lake& lake = lakes.lakes[k];
    feature.properties = {{"id", static_cast<int>(k)},
                          {"level_m", std::round(lake.level_m * 1000.0) / 1000.0},
                          {"area_m2", std::round(static_cast<double>(lake.cells) * cell_area)},
                          {"volume_m3", std::round(lake.volume_m3)}};
    features.push_back(std::move(feature));
  }
  return io::polygons_to_geojson(features, "lakes");
}

}  // namespace sansui::scene

#include "scene/water_geojson.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "contour/extract.hpp"
#include "contour/geometry.hpp"
#include "contour/grid_frame.hpp"
#include "io/geojson_features.hpp"

namespace sansui::scene {

nlohmann::json reach_properties(const ReachProperties& reach) {
  return {{"id", reach.id},
          {"strahler", reach.strahler_order},
          {"area_m2", std::round(reach.area_m2)},
          {"discharge_m3_s", std::round(reach.discharge_m3_per_s * 1e4) / 1e4}};
}

std::string rivers_to_geojson(const water::RiverNetwork& rivers, const Heightfield& grid) {
  const auto frame = contour::GridFrame::of(grid);
  std::vector<io::LineFeature> features;
  int id = 0;
  for (const water::River& river : rivers.rivers) {
    if (river.cells.size() < 2) continue;  // a line needs two positions
    features.push_back(
        river_feature(river.cells, grid.width(), frame, {id++, river.strahler_order, river.area_m2, river.discharge_m3_per_s}));
  }
  return io::lines_to_geojson(features, "rivers");
}

namespace {

/// Twice the signed area of `ring` as written (east, north): positive counter-clockwise.
double doubled_area(const std::vector<io::Position>& ring) {
  double sum = 0.0;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) sum += ring[j][0] * ring[i][1] - ring[i][0] * ring[j][1];
  return sum;
}

/// Whether `point` lies inside `ring` (even-odd rule).
bool inside(const std::vector<io::Position>& ring, const io::Position& point) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    if ((ring[i][1] > point[1]) != (ring[j][1] > point[1]) &&
        point[0] < ring[j][0] + (point[1] - ring[j][1]) * (ring[i][0] - ring[j][0]) / (ring[i][1] - ring[j][1]))
      in = !in;
  return in;
}

/// The rings of one lake's shore as valid OGC polygons: the rings one inside no other (or inside
/// an even number) are shells, each a polygon, counter-clockwise as RFC 7946 asks; a ring inside
/// one shell is an island, a hole of the innermost shell around it, clockwise. Marching squares
/// on a bordered mask gives closed rings that never cross or touch.
std::vector<io::PolygonRings> shells_with_holes(const std::vector<contour::Ring>& rings) {
  std::vector<std::vector<io::Position>> all;
  for (const contour::Ring& ring : rings) {
    if (ring.size() < 3) continue;
    std::vector<io::Position> positions;
    for (const contour::Point& p : ring) positions.push_back({p.x, p.y});
    all.push_back(std::move(positions));
  }
  // Largest first, so that every ring's enclosers come before it.
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& c) { return std::abs(doubled_area(a)) > std::abs(doubled_area(c)); });
  std::vector<io::PolygonRings> polygons;
  std::vector<int> depth(all.size(), 0), shell_of(all.size(), -1);
  for (std::size_t i = 0; i < all.size(); ++i) {
    int innermost = -1;
    for (std::size_t j = 0; j < i; ++j)
      if (inside(all[j], all[i].front())) {
        ++depth[i];
        if (innermost < 0 || std::abs(doubled_area(all[j])) < std::abs(doubled_area(all[static_cast<std::size_t>(innermost)])))
          innermost = static_cast<int>(j);
      }
    const bool is_shell = depth[i] % 2 == 0;
    if (is_shell == (doubled_area(all[i]) < 0.0)) std::reverse(all[i].begin(), all[i].end());
    if (is_shell) {
      shell_of[i] = static_cast<int>(polygons.size());
      polygons.push_back({all[i]});
    } else {
      polygons[static_cast<std::size_t>(shell_of[static_cast<std::size_t>(innermost)])].push_back(all[i]);
    }
  }
  return polygons;
}

}  // namespace

LakeShore::LakeShore(const Rect& box, const contour::GridFrame& frame)
    : box_(box), mask_(box.width() + 2, box.height() + 2, 0.0f, frame.cell_m) {
  mask_.origin_x_m = frame.origin_x_m + (box.x0 - 1) * frame.cell_m;
  mask_.origin_y_m = frame.origin_y_m + (box.y0 - 1) * frame.cell_m;
}

io::PolygonFeature LakeShore::feature(const LakeProperties& lake) const {
  io::PolygonFeature feature{shells_with_holes(contour::extract_contours(mask_, 0.5)), {}};
  const double cell_area = mask_.cell_size_m * mask_.cell_size_m;
  feature.properties = {{"id", lake.id},
                        {"level_m", std::round(lake.level_m * 1000.0) / 1000.0},
                        {"area_m2", std::round(static_cast<double>(lake.cells) * cell_area)},
                        {"volume_m3", std::round(lake.volume_m3)}};
  return feature;
}

std::string lakes_to_geojson(const water::LakeFill& lakes, const Heightfield& ground) {
  const int width = ground.width(), height = ground.height();
  // Each lake's bounding box, so that its outline is traced on a small mask.
  std::vector<Rect> boxes(lakes.lakes.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (const std::int32_t label = lakes.lake(x, y); label > 0) add_to_box(boxes[static_cast<std::size_t>(label - 1)], x, y);
  const auto frame = contour::GridFrame::of(ground);
  std::vector<io::PolygonFeature> features;
  for (std::size_t k = 0; k < lakes.lakes.size(); ++k) {
    const Rect& box = boxes[k];
    if (box.empty()) continue;
    LakeShore shore(box, frame);
    const auto label = static_cast<std::int32_t>(k + 1);
    for (int y = box.y0; y < box.y1; ++y)
      for (int x = box.x0; x < box.x1; ++x)
        if (lakes.lake(x, y) == label) shore.add(x, y);
    const water::Lake& lake = lakes.lakes[k];
    features.push_back(shore.feature({static_cast<int>(k), lake.level_m, lake.cells, lake.volume_m3}));
  }
  return io::polygons_to_geojson(features, "lakes");
}

}  // namespace sansui::scene

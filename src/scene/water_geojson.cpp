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
std::vector<io::PolygonFeature> shells_with_holes(const std::vector<contour::Ring>& rings) {
  std::vector<std::vector<io::Position>> all;
  for (const contour::Ring& ring : rings) {
    if (ring.size() < 3) continue;
    std::vector<io::Position> positions;
    for (const contour::Point& p : ring) positions.push_back({p.x, p.y});
    all.push_back(std::move(positions));
  }
  // Largest first, so that every ring's enclosers come before it.
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& c) { return std::abs(doubled_area(a)) > std::abs(doubled_area(c)); });
  std::vector<io::PolygonFeature> polygons;
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
      polygons.push_back({{all[i]}, {}});
    } else {
      polygons[static_cast<std::size_t>(shell_of[static_cast<std::size_t>(innermost)])].rings.push_back(all[i]);
    }
  }
  return polygons;
}

}  // namespace

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
    // The mask has a border of dry cells, so that every ring closes inside it.
    Heightfield mask(b.x1 - b.x0 + 3, b.y1 - b.y0 + 3, 0.0f, ground.cell_size_m);
    mask.origin_x_m = ground.origin_x_m + (b.x0 - 1) * ground.cell_size_m;
    mask.origin_y_m = ground.origin_y_m + (b.y0 - 1) * ground.cell_size_m;
    const auto label = static_cast<std::int32_t>(k + 1);
    for (int y = b.y0; y <= b.y1; ++y)
      for (int x = b.x0; x <= b.x1; ++x) mask(x - b.x0 + 1, y - b.y0 + 1) = lakes.lake(x, y) == label ? 1.0f : 0.0f;
    // A lake whose cells touch only at corners is several polygons: each gets its share of the
    // lake's area and volume, by its own area.
    const water::Lake& lake = lakes.lakes[k];
    std::vector<io::PolygonFeature> parts = shells_with_holes(contour::extract_contours(mask, 0.5));
    std::vector<double> areas;
    double total = 0.0;
    for (const io::PolygonFeature& part : parts) {
      double area = 0.0;
      for (const auto& ring : part.rings) area += 0.5 * doubled_area(ring);  // holes are clockwise: they subtract
      areas.push_back(area);
      total += area;
    }
    for (std::size_t p = 0; p < parts.size(); ++p) {
      const double share = total > 0.0 ? areas[p] / total : 1.0 / static_cast<double>(parts.size());
      parts[p].properties = {{"id", static_cast<int>(k)},
                             {"level_m", std::round(lake.level_m * 1000.0) / 1000.0},
                             {"area_m2", std::round(share * static_cast<double>(lake.cells) * cell_area)},
                             {"volume_m3", std::round(share * lake.volume_m3)}};
      features.push_back(std::move(parts[p]));
    }
  }
  return io::polygons_to_geojson(features, "lakes");
}

}  // namespace sansui::scene

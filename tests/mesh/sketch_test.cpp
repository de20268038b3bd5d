#include "mesh/sketch.hpp"

#include <cmath>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/sketch_geojson.hpp"
#include "mesh/edge_mesh.hpp"
#include "mesh/mesh_test_util.hpp"

namespace sansui::mesh {
namespace {

using ::testing::HasSubstr;

SketchFeature line(std::vector<SketchPoint> points, std::string label, bool locked = false) {
  return {std::move(points), locked, std::move(label)};
}

/// A ridge from west to east rising to a peak, a valley to the south, a spot height north.
Sketch small_sketch() {
  Sketch s;
  s.features.push_back(line({{0, 500, 300}, {400, 520, 700}, {800, 480, 900}, {1200, 500, 500}}, "feature 1 (ridge)", true));
  s.features.push_back(line({{100, 0, 100}, {600, 100, 200}, {1100, 50, 120}}, "feature 2 (valley)"));
  s.features.push_back(line({{600, 1000, 250}}, "feature 3 (spot)"));
  return s;
}

std::string error_of(const Sketch& sketch, const SketchParams& params = {}) {
  try {
    triangulate_sketch(sketch, params);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

/// Undirected edges of a mesh as pairs of (east, north) places.
std::set<std::pair<std::pair<float, float>, std::pair<float, float>>> edges_of(const TriangleMesh& m) {
  std::set<std::pair<std::pair<float, float>, std::pair<float, float>>> out;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) {
      const glm::vec3 a = m.positions[m.indices[3 * t + i]], b = m.positions[m.indices[3 * t + (i + 1) % 3]];
      std::pair<float, float> pa{a.x, -a.z}, pb{b.x, -b.z};
      out.insert({std::min(pa, pb), std::max(pa, pb)});
    }
  return out;
}

TEST(Sketch, EveryDrawnSegmentIsAnEdgeAndEveryPointKeepsItsHeight) {
  const Sketch sketch = small_sketch();
  const SketchMesh out = triangulate_sketch(sketch);
  EXPECT_EQ(out.mesh.positions.size(), 8u);
  const auto edges = edges_of(out.mesh);
  for (const SketchFeature& f : sketch.features)
    for (std::size_t k = 1; k < f.points.size(); ++k) {
      std::pair<float, float> a{float(f.points[k - 1].east_m), float(f.points[k - 1].north_m)};
      std::pair<float, float> b{float(f.points[k].east_m), float(f.points[k].north_m)};
      EXPECT_TRUE(edges.count({std::min(a, b), std::max(a, b)})) << f.label << " segment " << k;
    }
  for (const SketchFeature& f : sketch.features)
    for (const SketchPoint& p : f.points) {
      bool found = false;
      for (std::size_t v = 0; v < out.mesh.positions.size(); ++v) {
        const glm::vec3 q = out.mesh.positions[v];
        if (q.x == float(p.east_m) && q.z == float(-p.north_m)) {
          found = true;
          EXPECT_EQ(q.y, float(p.height_m));
          EXPECT_EQ(out.locked[v] != 0, f.locked);
        }
      }
      EXPECT_TRUE(found);
    }
  // Faces up, and a valid surface.
  for (std::size_t t = 0; t < out.mesh.triangle_count(); ++t) {
    const glm::vec3 a = out.mesh.positions[out.mesh.indices[3 * t]], b = out.mesh.positions[out.mesh.indices[3 * t + 1]],
                    c = out.mesh.positions[out.mesh.indices[3 * t + 2]];
    EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
  }
  BuildReport report;
  test::expect_valid_surface(build_edge_mesh(out.mesh, out.locked, &report));
  EXPECT_EQ(report.flipped_triangles, 0u);
}

TEST(Sketch, RefinementBoundsEdgesAndInterpolatesHeights) {
  // Every point on the plane height = 0.1 east + 0.2 north: new points must land on it too.
  Sketch s;
  auto on_plane = [](double e, double n) { return SketchPoint{e, n, 0.1 * e + 0.2 * n}; };
  s.features.push_back(line({on_plane(0, 0), on_plane(1000, 100), on_plane(900, 800)}, "feature 1"));
  s.features.push_back(line({on_plane(100, 700), on_plane(400, 400)}, "feature 2"));
  SketchParams params;
  params.max_edge_m = 120;
  const SketchMesh out = triangulate_sketch(s, params);
  EXPECT_GT(out.mesh.triangle_count(), 100u);
  for (glm::vec3 p : out.mesh.positions) EXPECT_NEAR(p.y, 0.1 * p.x + 0.2 * -p.z, 1e-3);
  for (std::size_t t = 0; t < out.mesh.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) {
      const glm::vec3 a = out.mesh.positions[out.mesh.indices[3 * t + i]], b = out.mesh.positions[out.mesh.indices[3 * t + (i + 1) % 3]];
      EXPECT_LE(std::hypot(a.x - b.x, a.z - b.z), 120.0 * 1.001);
    }
}

TEST(Sketch, FrameAddsFourCornersAtTheBaseHeight) {
  SketchParams params;
  params.frame_margin_m = 200;
  params.frame_height_m = -50;
  const SketchMesh out = triangulate_sketch(small_sketch(), params);
  int corners = 0;
  for (glm::vec3 p : out.mesh.positions)
    if ((p.x == -200 || p.x == 1400) && (p.z == 200 || p.z == -1200)) {
      ++corners;
      EXPECT_EQ(p.y, -50.0f);
    }
  EXPECT_EQ(corners, 4);
  params.frame_height_m.reset();
  for (glm::vec3 p : triangulate_sketch(small_sketch(), params).mesh.positions)
    if (p.x == -200 && p.z == 200) {
      EXPECT_EQ(p.y, 100.0f);  // the lowest height drawn
    }
}

TEST(Sketch, BadSketchesAreRefusedWithAMessage) {
  EXPECT_THAT(error_of(Sketch{}), HasSubstr("the sketch has no lines or points"));

  Sketch crossing = small_sketch();
  crossing.features.push_back(line({{600, 300, 0}, {600, 700, 0}}, "feature 4"));
  EXPECT_THAT(error_of(crossing), HasSubstr("feature 1 (ridge) and feature 4 cross or touch at (east 600, north"));

  Sketch touching = small_sketch();  // ends on the valley line between its points
  touching.features.push_back(line({{350, 300, 0}, {350, 50, 0}}, "feature 4"));
  EXPECT_THAT(error_of(touching), HasSubstr("feature 2 (valley) and feature 4 cross or touch at (east 350, north 50)"));

  Sketch heights = small_sketch();
  heights.features.push_back(line({{400, 520, 650}, {400, 800, 300}}, "feature 4"));
  EXPECT_THAT(error_of(heights),
              HasSubstr("the map point (east 400, north 520) has two heights: 700 m in feature 1 (ridge) and 650 m in feature 4"));

  Sketch self = small_sketch();
  self.features.push_back(line({{0, 800, 0}, {200, 900, 0}, {200, 800, 0}, {0, 900, 0}}, "feature 4"));
  EXPECT_THAT(error_of(self), HasSubstr("feature 4 crosses or runs back over itself"));

  Sketch back = small_sketch();
  back.features.push_back(line({{0, 800, 0}, {200, 800, 0}, {100, 800, 0}}, "feature 4"));
  EXPECT_THAT(error_of(back), HasSubstr("feature 4 crosses or runs back over itself at (east 200, north 800)"));

  Sketch spot = small_sketch();
  spot.features.push_back(line({{350, 50, 0}}, "feature 4 (spot)"));
  EXPECT_THAT(error_of(spot), HasSubstr("feature 4 (spot) lies on feature 2 (valley) between two of its points"));

  Sketch repeated = small_sketch();
  repeated.features[1].points.insert(repeated.features[1].points.begin() + 1, repeated.features[1].points[1]);
  EXPECT_THAT(error_of(repeated), HasSubstr("feature 2 (valley) has the point (east 600, north 100) twice in a row"));

  Sketch nan = small_sketch();
  nan.features[2].points[0].height_m = NAN;
  EXPECT_THAT(error_of(nan), HasSubstr("feature 3 (spot) has a point that is not finite numbers"));

  Sketch few;
  few.features.push_back(line({{0, 0, 0}, {10, 0, 0}}, "feature 1"));
  EXPECT_THAT(error_of(few), HasSubstr("the sketch has 2 distinct map points: a surface needs at least three"));

  Sketch flat;
  flat.features.push_back(line({{0, 0, 0}, {10, 0, 0}, {20, 0, 5}}, "feature 1"));
  EXPECT_THAT(error_of(flat), HasSubstr("all points of the sketch lie on one line"));

  Sketch empty_feature = small_sketch();
  empty_feature.features.push_back(line({}, "feature 4"));
  EXPECT_THAT(error_of(empty_feature), HasSubstr("feature 4 has no points"));

  SketchParams bad;
  bad.max_edge_m = -1;
  EXPECT_THAT(error_of(small_sketch(), bad), HasSubstr("sketch.refine -1 is not allowed: it must be between 0 and 10000000 m"));
  bad = {};
  bad.frame_margin_m = NAN;
  EXPECT_THAT(error_of(small_sketch(), bad), HasSubstr("sketch.frame nan is not allowed"));
  bad = {};
  bad.max_edge_m = 0.01;
  EXPECT_THAT(error_of(small_sketch(), bad), HasSubstr("sketch max edge 0.01 m would make about"));
}

// --- GeoJSON ---

std::string geojson_error(const std::string& text) {
  try {
    io::parse_sketch_geojson(text, "s.geojson");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SketchGeoJson, ReadsHeightsFromCoordinatesArraysOrOneProperty) {
  const Sketch s = io::parse_sketch_geojson(R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "Main", "kind": "ridge", "lock": true},
     "geometry": {"type": "LineString", "coordinates": [[0, 0, 10], [100, 0, 20]]}},
    {"type": "Feature", "properties": {"height": 5},
     "geometry": {"type": "MultiLineString", "coordinates": [[[0, 50], [100, 50]], [[0, 80], [50, 90]]]}},
    {"type": "Feature", "properties": {"heights": [1, 2, 3]},
     "geometry": {"type": "LineString", "coordinates": [[0, 200], [50, 210], [100, 200]]}},
    {"type": "Feature", "properties": null, "geometry": {"type": "Point", "coordinates": [40, 300, 77]}},
    {"type": "Feature", "properties": {}, "geometry": null},
    {"type": "Feature", "properties": {"height": 9},
     "geometry": {"type": "Polygon", "coordinates": [[[200, 0], [300, 0], [300, 100], [200, 0]]]}}
  ]})",
                                            "s.geojson");
  ASSERT_EQ(s.features.size(), 6u);
  EXPECT_EQ(s.features[0].label, "feature 1 (Main, ridge)");
  EXPECT_TRUE(s.features[0].locked);
  EXPECT_EQ(s.features[0].points[1].height_m, 20);
  EXPECT_EQ(s.features[1].label, "feature 2, line 1");
  EXPECT_EQ(s.features[2].points[0].height_m, 5);
  EXPECT_EQ(s.features[3].points[2].height_m, 3);
  EXPECT_EQ(s.features[4].points.size(), 1u);
  EXPECT_EQ(s.features[4].points[0].height_m, 77);
  EXPECT_EQ(s.features[5].points.size(), 4u);
  EXPECT_FALSE(s.features[1].locked);
}

TEST(SketchGeoJson, BadFilesAreRefusedWithAMessage) {
  EXPECT_THAT(geojson_error("{\"type\": "), HasSubstr("s.geojson: not valid JSON"));
  EXPECT_THAT(geojson_error("[1, 2]"), HasSubstr("s.geojson is not GeoJSON"));
  EXPECT_THAT(geojson_error(R"({"type": "FeatureCollection"})"), HasSubstr("has no \"features\" array"));
  EXPECT_THAT(geojson_error(R"({"type": "FeatureCollection", "features": []})"), HasSubstr("s.geojson has no lines or points"));
  EXPECT_THAT(geojson_error(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
      "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 1]]}}]})"),
              HasSubstr("s.geojson: feature 1 has no height"));
  EXPECT_THAT(geojson_error(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"height": 1},
      "geometry": {"type": "LineString", "coordinates": [[0, 0]]}}]})"),
              HasSubstr("feature 1 needs at least 2 positions"));
  EXPECT_THAT(geojson_error(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"height": 1},
      "geometry": {"type": "LineString", "coordinates": [[0, "x"], [1, 1]]}}]})"),
              HasSubstr("has a position that is not [east, north] or [east, north, height] numbers"));
  EXPECT_THAT(geojson_error(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"height": "high"},
      "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 1]]}}]})"),
              HasSubstr("has a \"height\" that is not a number"));
  EXPECT_THAT(geojson_error(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
      "geometry": {"type": "GeometryCollection", "geometries": []}}]})"),
              HasSubstr("has geometry type \"GeometryCollection\": allowed are LineString"));
  EXPECT_THAT(geojson_error(R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"lock": "yes", "height": 1},
      "geometry": {"type": "Point", "coordinates": [0, 0]}}]})"),
              HasSubstr("has a \"lock\" that is not true or false"));
  try {
    io::read_sketch_geojson("/nonexistent/ridges.geojson");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot read /nonexistent/ridges.geojson: No such file or directory"));
  }
}

}  // namespace
}  // namespace sansui::mesh

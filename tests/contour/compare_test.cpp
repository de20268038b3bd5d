#include "contour/compare.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "contour/generate.hpp"
#include "contour/grid_frame.hpp"
#include "contour/map_drawing.hpp"
#include "contour/map_raster.hpp"
#include "core/error.hpp"
#include "io/map_svg.hpp"
#include "scene/contour_geojson.hpp"
#include "tests/contour/contour_test_util.hpp"

namespace sansui::contour {
namespace {

/// Cones of height `peak` and slope 1 (45 degrees) at the given centres, on 2 m cells.
Heightfield cones(std::vector<std::pair<Point, double>> peaks, int size = 201) {
  Heightfield h(size, size, 0.0f, 2.0);
  const GridFrame frame = GridFrame::of(h);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      double z = 0.0;
      for (const auto& [c, top] : peaks) z = std::max(z, top - distance(frame.at(i, j), c));
      h(i, j) = static_cast<float>(z);
    }
  return h;
}

TEST(Compare, AConeHasTheConesHypsometryAndSlope) {
  const Heightfield cone = cones({{{200, -200}, 150.0}}, 201);
  const DemMeasures m = measure_dem(cone, {1.0, nullptr}, {50.0, 100.0}, 10.0);
  // Area above relative height h of a cone: (1 - h)^2, integral 1/3.
  EXPECT_NEAR(m.hypsometric_integral, 1.0 / 3.0, 0.02);
  EXPECT_NEAR(m.hypsometry[50], 0.25, 0.02);
  EXPECT_NEAR(m.mean_slope_deg, 45.0, 1.0);
  EXPECT_EQ(m.summits, 1);
  // Contour length at 50 m: a circle of radius 100 m.
  EXPECT_NEAR(m.contour_length_m[0], 2.0 * 3.14159265 * 100.0, 2.0);
}

TEST(Compare, CountsSummitsByProminence) {
  // Peaks of 150, 120 and 95 m; the saddles lie at 150 - 90 = 60 m and 95 - 40 = 55 m or so.
  const Heightfield h = cones({{{100, -100}, 150.0}, {{280, -120}, 120.0}, {{200, -300}, 95.0}}, 201);
  EXPECT_EQ(measure_dem(h, {}, {}, 10.0).summits, 3);
  EXPECT_EQ(measure_dem(h, {}, {}, 200.0).summits, 0);
  EXPECT_EQ(measure_dem(h, {}, {}, 140.0).summits, 1);  // only the highest stands 150 m above the plain
}

TEST(Compare, ADemComparedWithItselfDiffersInNothing) {
  const Heightfield h = cones({{{100, -100}, 150.0}, {{280, -120}, 120.0}}, 201);
  const Comparison c = compare_dems(h, h, {});
  EXPECT_EQ(c.hypsometric_difference, 0.0);
  EXPECT_EQ(c.slope_distance_deg, 0.0);
  EXPECT_DOUBLE_EQ(c.length_ratio, 1.0);
  EXPECT_EQ(c.real.summits, c.generated.summits);
  EXPECT_EQ(c.real.dem_spectrum_slope, c.generated.dem_spectrum_slope);
  const std::string table = comparison_table(c);
  EXPECT_NE(table.find("hypsometric integral"), std::string::npos);
  EXPECT_NE(table.find("DEM power spectrum slope"), std::string::npos);
}

TEST(Compare, OnlyCellsInsideTheRingCount) {
  const Heightfield h = cones({{{100, -100}, 150.0}, {{300, -300}, 120.0}}, 201);
  CompareParams params;
  params.inside = test::circle({100, -100}, 60.0, 64);
  const Comparison c = compare_dems(h, h, params);
  EXPECT_EQ(c.real.summits, 1);
  EXPECT_NEAR(static_cast<double>(c.real.cells), 3.14159265 * 30.0 * 30.0, 60.0);  // radius 60 m = 30 cells
}

TEST(Compare, DifferentShapesShowDifferences) {
  const Heightfield steep = cones({{{200, -200}, 150.0}});
  Heightfield gentle = steep;
  for (float& z : gentle.values()) z = 150.0f * std::pow(z / 150.0f, 2.0f);  // concave: less area high up
  const Comparison c = compare_dems(steep, gentle, {});
  EXPECT_GT(c.hypsometric_difference, 0.05);
  EXPECT_GT(c.slope_distance_deg, 5.0);
  EXPECT_LT(c.generated.hypsometric_integral, c.real.hypsometric_integral);
}

TEST(Compare, BadInputsAreRejected) {
  const Heightfield h = cones({{{200, -200}, 150.0}});
  CompareParams too_high;
  too_high.above_m = 1000.0;
  EXPECT_THROW(compare_dems(h, h, too_high), InputError);
  CompareParams negative;
  negative.interval_m = -1.0;
  EXPECT_THROW(compare_dems(h, h, negative), InputError);
  Heightfield low(50, 50, 0.0f, 2.0), high(50, 50, 500.0f, 2.0);
  low(25, 25) = 10.0f;
  high(25, 25) = 600.0f;
  EXPECT_THROW(compare_dems(low, high, {}), InputError);
}

ContourTree small_tree() {
  GenerationParams p;
  p.method = Method::midpoint;
  p.offset_m = 8.0;
  p.outward_levels = 1;
  return generate_contours(test::circle({10, 20}, 60.0, 48), p);
}

TEST(GeoJson, RoundTripKeepsRingsLevelsElevationsAndParents) {
  const ContourTree tree = small_tree();
  const ContourTree back = scene::contours_from_geojson(scene::contours_to_geojson(tree), "mem");
  ASSERT_EQ(back.nodes.size(), tree.nodes.size());
  EXPECT_EQ(back.seed, tree.seed);
  for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
    EXPECT_EQ(back.nodes[i].level, tree.nodes[i].level);
    EXPECT_EQ(back.nodes[i].parent, tree.nodes[i].parent);
    EXPECT_EQ(back.nodes[i].children, tree.nodes[i].children);
    EXPECT_DOUBLE_EQ(back.nodes[i].elevation_m, tree.nodes[i].elevation_m);
    ASSERT_EQ(back.nodes[i].ring.size(), tree.nodes[i].ring.size());
    for (std::size_t k = 0; k < tree.nodes[i].ring.size(); ++k) EXPECT_LE(distance(back.nodes[i].ring[k], tree.nodes[i].ring[k]), 0.001);
  }
  EXPECT_THROW(scene::contours_from_geojson(R"({"type":"FeatureCollection","features":[{"type":"Feature"}]})", "x"), InputError);
  // Levels, parents and the seed index must be whole numbers that fit (a fuzzed 1e63 level was
  // undefined behaviour), and the seed one of the contours (it indexes them).
  const auto message_of = [](const std::string& text) -> std::string {
    try {
      scene::contours_from_geojson(text, "x");
    } catch (const InputError& e) {
      return e.what();
    }
    return "<no InputError>";
  };
  const std::string ring = R"("geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]})";
  for (const auto& [properties, message] : std::vector<std::pair<std::string, std::string>>{
           {R"({"level":1e63,"elevation_m":0})", "feature 0 has level 1e+63: it must be a whole number"},
           {R"({"level":"0","elevation_m":0})", "feature 0 has level \"0\": it must be a whole number"},
           {R"({"level":0,"elevation_m":0,"parent":2.5})", "feature 0 has parent 2.5: it must be a whole number"}}) {
    const std::string text = R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":)" + properties + "," + ring + "}]}";
    EXPECT_NE(message_of(text).find(message), std::string::npos) << message_of(text);
  }
  const std::string seed_out_of_range =
      R"({"type":"FeatureCollection","sansui":{"seed_contour":5},"features":[{"type":"Feature","properties":{"level":0,"elevation_m":0},)" +
      ring + "}]}";
  EXPECT_NE(message_of(seed_out_of_range).find("its seed contour 5 is not one of its 1 contours"), std::string::npos)
      << message_of(seed_out_of_range);
}

TEST(ContourMap, IndexContoursAreBoldAndLabelled) {
  const ContourTree tree = small_tree();
  MapStyle style;
  style.width_px = 400;
  const MapDrawing map = layout_contour_map(tree, style);
  EXPECT_EQ(map.width_px, 400);
  int thin = 0, bold = 0, labels = 0;
  for (const MapItem& item : map.items) {
    if (const auto* s = std::get_if<MapStroke>(&item)) {
      if (s->colour == style.contour) (s->width_px == style.index_line_px ? bold : thin)++;
    }
    if (const auto* l = std::get_if<MapLabel>(&item)) labels += l->text == "0" || l->text.ends_with(" m") ? 0 : 1;
  }
  int index = 0;
  for (const ContourNode& n : tree.nodes) index += is_index_level(n.level, 0.0, 10.0, 5) ? 1 : 0;
  EXPECT_EQ(bold, index);
  EXPECT_EQ(thin + bold, static_cast<int>(tree.nodes.size()));
  EXPECT_GE(labels, 1);
  const std::string svg = io::map_to_svg(map);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  const Image image = rasterize_map(map);
  EXPECT_EQ(image.width(), map.width_px);
  EXPECT_EQ(image.height(), map.height_px);
  int inked = 0;
  for (const Rgba8& p : image.values()) inked += p == style.paper ? 0 : 1;
  EXPECT_GT(inked, 1000);
}

TEST(ContourMap, IndexLevelsFollowElevationsWhenZ0IsAMultipleOfTheInterval) {
  EXPECT_TRUE(is_index_level(0, 0.0, 10.0, 5));
  EXPECT_TRUE(is_index_level(5, 0.0, 10.0, 5));
  EXPECT_FALSE(is_index_level(3, 0.0, 10.0, 5));
  EXPECT_TRUE(is_index_level(2, 30.0, 10.0, 5));   // 30 + 20 = 50 m
  EXPECT_TRUE(is_index_level(-3, 30.0, 10.0, 5));  // 0 m
  EXPECT_TRUE(is_index_level(5, 33.0, 10.0, 5));   // z0 not on the grid: every fifth from the seed
}

}  // namespace
}  // namespace sansui::contour

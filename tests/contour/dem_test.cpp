#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "contour/edt.hpp"
#include "contour/elevations.hpp"
#include "contour/extract.hpp"
#include "contour/generate.hpp"
#include "contour/grid_frame.hpp"
#include "contour/to_dem.hpp"
#include "core/error.hpp"
#include "core/random.hpp"
#include "io/hypsometry_csv.hpp"
#include "tests/contour/contour_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui::contour {
namespace {

Ring ellipse(int vertices = 120) {
  Ring ring;
  for (int i = 0; i < vertices; ++i) {
    const double a = 2.0 * std::numbers::pi * i / vertices;
    ring.push_back({300.0 * std::cos(a) + 30.0 * std::cos(3 * a), 180.0 * std::sin(a)});
  }
  return ring;
}

ContourTree mountain(Method method, const Ring& seed = ellipse()) {
  GenerationParams p;
  p.method = method;
  p.offset_m = 15.0;
  p.interval_m = 10.0;
  p.z0_m = 200.0;
  p.outward_levels = 2;
  p.samples = 256;
  p.f0 = 64;
  return generate_contours(seed, p);
}

/// Every cell lies between the contour below it and the contours above it.
void expect_bracketed(const ContourTree& tree, const Heightfield& dem, const DemParams& params, double cap) {
  const auto labels = innermost_contour(tree, params);
  double base = INFINITY;
  for (int r : tree.roots()) base = std::min(base, tree.nodes[static_cast<std::size_t>(r)].elevation_m);
  for (int j = 0; j < dem.height(); ++j)
    for (int i = 0; i < dem.width(); ++i) {
      const int l = labels(i, j);
      const double z = dem(i, j);
      if (l < 0) {
        ASSERT_EQ(z, static_cast<float>(base)) << i << "," << j;
        continue;
      }
      const ContourNode& node = tree.nodes[static_cast<std::size_t>(l)];
      const double upper =
          node.children.empty() ? node.elevation_m + cap : tree.nodes[static_cast<std::size_t>(node.children[0])].elevation_m;
      ASSERT_GE(z, static_cast<float>(node.elevation_m)) << i << "," << j;
      ASSERT_LE(z, static_cast<float>(upper)) << i << "," << j;
    }
}

TEST(ContoursToDem, EveryCellLiesBetweenItsBracketingContours) {
  for (Method method : {Method::simple, Method::revised}) {
    const ContourTree tree = mountain(method);
    DemParams params = dem_frame_for(tree, 257);
    params.offset_m = 15.0;
    const Heightfield dem = contours_to_dem(tree, params);
    expect_bracketed(tree, dem, params, 10.0);
    params.roughness_m = 20.0;
    const Heightfield rough = contours_to_dem(tree, params);
    expect_bracketed(tree, rough, params, 10.0);
    EXPECT_NE(sansui::test::fnv1a(rough.values()), sansui::test::fnv1a(dem.values()));
  }
}

/// Largest distance from any point of `from` to the nearest of `to`.
double farthest(const std::vector<Ring>& from, const std::vector<Ring>& to) {
  double worst = 0.0;
  for (const Ring& ring : from)
    for (const Point& p : ring) {
      double best = INFINITY;
      for (const Ring& other : to) best = std::min(best, distance_to_ring(other, p));
      worst = std::max(worst, best);
    }
  return worst;
}

TEST(ContoursToDem, ContoursOfTheDemAreTheGeneratedContoursWithinOneCell) {
  for (Method method : {Method::simple, Method::revised}) {
    const ContourTree tree = mountain(method);
    DemParams params = dem_frame_for(tree, 401);
    params.offset_m = 15.0;
    const Heightfield dem = contours_to_dem(tree, params);
    const double cell = params.cell_m;
    int low = 0, high = 0;
    for (const ContourNode& n : tree.nodes) low = std::min(low, n.level), high = std::max(high, n.level);
    for (int level = low + 1; level <= high; ++level) {  // the lowest is the base: no edge to find
      std::vector<Ring> generated;
      double z = 0.0;
      for (const ContourNode& n : tree.nodes)
        if (n.level == level) generated.push_back(n.ring), z = n.elevation_m;
      const std::vector<Ring> extracted = extract_contours(dem, z);
      ASSERT_FALSE(extracted.empty()) << "level " << level;
      EXPECT_LE(farthest(extracted, generated), cell * (1.0 + 1e-9)) << name_of(method) << " level " << level;
      if (method == Method::simple) {
        EXPECT_LE(farthest(generated, extracted), 1.5 * cell) << "level " << level;
      }
    }
  }
}

TEST(ContoursToDem, SummitCapRisesAtMostOneInterval) {
  const ContourTree tree = mountain(Method::simple);
  DemParams params = dem_frame_for(tree, 257);
  params.offset_m = 15.0;
  const Heightfield dem = contours_to_dem(tree, params);
  double top = 0.0;
  for (const ContourNode& n : tree.nodes) top = std::max(top, n.elevation_m);
  const float highest = *std::max_element(dem.values().begin(), dem.values().end());
  EXPECT_GT(highest, top);
  EXPECT_LE(highest, top + 10.0);
}

TEST(ContoursToDem, SameBytesWithAnyThreadCount) {
  const ContourTree tree = mountain(Method::revised);
  DemParams params = dem_frame_for(tree, 300);
  params.roughness_m = 5.0;
  const Heightfield all = contours_to_dem(tree, params);
  tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
  const Heightfield one = contours_to_dem(tree, params);
  EXPECT_EQ(sansui::test::fnv1a(one.values()), sansui::test::fnv1a(all.values()));
}

TEST(ContoursToDem, FrameHoldsEveryContourWithAMargin) {
  const ContourTree tree = mountain(Method::simple);
  const DemParams params = dem_frame_for(tree, 513);
  EXPECT_EQ(std::max(params.width, params.height), 513);
  const GridFrame frame{params.origin_x_m, params.origin_y_m, params.cell_m};
  for (const ContourNode& n : tree.nodes)
    for (const Point& p : n.ring) {
      EXPECT_GT(frame.column(p.x), 5.0);
      EXPECT_LT(frame.column(p.x), params.width - 6.0);
      EXPECT_GT(frame.row(p.y), 5.0);
      EXPECT_LT(frame.row(p.y), params.height - 6.0);
    }
}

TEST(ContoursToDem, BadParametersAreRejected) {
  const ContourTree tree = mountain(Method::simple);
  DemParams params = dem_frame_for(tree, 64);
  params.cell_m = 0.0;
  EXPECT_THROW(contours_to_dem(tree, params), InputError);
  params = dem_frame_for(tree, 64);
  params.width = 1;
  EXPECT_THROW(contours_to_dem(tree, params), InputError);
  params = dem_frame_for(tree, 64);
  params.roughness_m = -1.0;
  EXPECT_THROW(contours_to_dem(tree, params), InputError);
}

TEST(DistanceTransform, NearestSourceIsTheBruteForceNearest) {
  Grid<std::uint8_t> sources(37, 23, 0);
  const std::uint64_t key = rng::stream_key(5, 1);
  for (int k = 0; k < 12; ++k) {
    const auto b = rng::bits(key, static_cast<std::uint64_t>(k));
    sources(static_cast<int>(b % 37), static_cast<int>((b >> 20) % 23)) = 1;
  }
  Grid<std::int32_t> nearest;
  nearest_source(sources, nearest);
  for (int y = 0; y < 23; ++y)
    for (int x = 0; x < 37; ++x) {
      long best = -1;
      for (int v = 0; v < 23; ++v)
        for (int u = 0; u < 37; ++u)
          if (sources(u, v) != 0) {
            const long d = static_cast<long>(u - x) * (u - x) + static_cast<long>(v - y) * (v - y);
            best = best < 0 ? d : std::min(best, d);
          }
      const int s = nearest(x, y);
      ASSERT_GE(s, 0);
      const int u = s % 37, v = s / 37;
      EXPECT_EQ(static_cast<long>(u - x) * (u - x) + static_cast<long>(v - y) * (v - y), best) << x << "," << y;
    }
  Grid<std::uint8_t> none(5, 5, 0);
  nearest_source(none, nearest);
  for (std::int32_t v : nearest.values()) EXPECT_EQ(v, -1);
}

TEST(Hypsometry, ReassignsElevationsByEnclosedArea) {
  ContourTree tree = mountain(Method::simple);
  // h = 1 - a: elevation proportional to the area above.
  const Hypsometry linear = io::parse_hypsometry("area,height\n1,0\n0,1\n", "curve.csv");
  apply_hypsometry(tree, linear, 500.0);
  int low = 0;
  const auto areas = area_per_level(tree, low);
  const double seed_area = areas[static_cast<std::size_t>(-low)];
  for (const ContourNode& n : tree.nodes) {
    if (n.level < 0) continue;
    EXPECT_NEAR(n.elevation_m, 200.0 + 500.0 * (1.0 - areas[static_cast<std::size_t>(n.level - low)] / seed_area), 1e-6);
  }
  // Elevations still rise with the level.
  for (const ContourNode& n : tree.nodes)
    if (n.parent >= 0) {
      EXPECT_GT(n.elevation_m, tree.nodes[static_cast<std::size_t>(n.parent)].elevation_m);
    }
}

TEST(Hypsometry, BadCurvesAreRejected) {
  EXPECT_THROW(io::parse_hypsometry("1,0\n", "c"), InputError);
  EXPECT_THROW(io::parse_hypsometry("1,0\n0.5,0.5\n0.6,1\n", "c"), InputError);  // area rises
  EXPECT_THROW(io::parse_hypsometry("1,0\n2,1\n", "c"), InputError);
  try {
    io::parse_hypsometry("1,0\nx,y\n0,1\n", "curve.csv");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("curve.csv:2"), std::string::npos) << e.what();
  }
}

TEST(OffsetSchedule, WiderSpacingMeansFewerLevels) {
  GenerationParams p;
  p.method = Method::simple;
  p.offset_m = 10.0;
  const auto uniform = generate_contours(ellipse(), p);
  p.offset_schedule_m = {10.0, 20.0, 30.0};
  const auto scheduled = generate_contours(ellipse(), p);
  EXPECT_LT(scheduled.nodes.size(), uniform.nodes.size());
  EXPECT_DOUBLE_EQ(p.offset_for_level(1), 10.0);
  EXPECT_DOUBLE_EQ(p.offset_for_level(3), 30.0);
  EXPECT_DOUBLE_EQ(p.offset_for_level(9), 30.0);
}

}  // namespace
}  // namespace sansui::contour

// contour-dem (issue 17 item 6): a DEM from a given contour map. The real case: the 40 m
// contours gdal_contour traced on examples/dem/jacksboro_ridge.tif (examples/contours/
// jacksboro_40m.geojson), rebuilt on the DEM's own grid and compared with it.
#include "contour/contours_to_dem.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include <gtest/gtest.h>

#include "contour/geometry.hpp"
#include "contour/grid_frame.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "io/contour_lines_geojson.hpp"
#include "io/heightmap_io.hpp"
#include "io/text_file.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::test {
namespace {

using contour::ContourLine;
using contour::ContourMap;
using contour::ContourMapGrid;
using contour::Point;

const std::string examples = std::string(sansui::test::source_dir) + "/examples/";

// GRASS r.surf.contour on the same contours and grid: RMSE 8.28 m (bench/peers_contour_dem.sh,
// docs/contour.md). The rebuild must be no worse.
constexpr double grass_rmse_m = 8.28;

struct Rebuilt {
  Heightfield real, dem;
};

Rebuilt rebuild_jacksboro() {
  Heightfield real = io::read_heightmap(examples + "dem/jacksboro_ridge.tif");
  const ContourMap map = io::parse_contour_map(io::read_text_file(examples + "contours/jacksboro_40m.geojson"), "jacksboro", "", false);
  const ContourMapGrid grid{real.width(), real.height(), real.cell_size_m, real.origin_x_m, real.origin_y_m};
  Heightfield dem = contour::contour_map_to_dem(map, grid);
  return {std::move(real), std::move(dem)};
}

/// Gradient magnitude by central differences, interior cells.
std::vector<double> gradients(const Heightfield& h) {
  std::vector<double> g;
  for (int j = 1; j + 1 < h.height(); ++j)
    for (int i = 1; i + 1 < h.width(); ++i) {
      const double gx = (h(i + 1, j) - h(i - 1, j)) / (2.0 * h.cell_size_m), gy = (h(i, j + 1) - h(i, j - 1)) / (2.0 * h.cell_size_m);
      g.push_back(std::hypot(gx, gy));
    }
  return g;
}

TEST(ContourMapToDem, RealContoursRebuildTheDemNoWorseThanGrass) {
  const auto [real, dem] = rebuild_jacksboro();
  double sum = 0.0;
  for (std::size_t k = 0; k < real.size(); ++k) sum += std::pow(double(dem.data()[k]) - real.data()[k], 2);
  const double rmse = std::sqrt(sum / static_cast<double>(real.size()));
  RecordProperty("rmse_m", std::to_string(rmse));
  EXPECT_LT(rmse, grass_rmse_m) << "RMSE " << rmse << " m";
}

TEST(ContourMapToDem, NoTerracesFlatCellsNoMoreThanInTheRealDem) {
  const auto [real, dem] = rebuild_jacksboro();
  // A terraced rebuild has a spike of near-zero slope on the bands between contours.
  auto flat_share = [](const std::vector<double>& g) {
    return static_cast<double>(std::count_if(g.begin(), g.end(), [](double v) { return v < 0.01; })) / static_cast<double>(g.size());
  };
  const double real_flat = flat_share(gradients(real)), rebuilt_flat = flat_share(gradients(dem));
  EXPECT_LT(rebuilt_flat, 2.0 * real_flat + 0.01) << "real " << real_flat << ", rebuilt " << rebuilt_flat;
  // And the slope histogram is not bimodal: its 10th percentile is well above zero.
  std::vector<double> g = gradients(dem), r = gradients(real);
  std::sort(g.begin(), g.end());
  std::sort(r.begin(), r.end());
  EXPECT_GT(g[g.size() / 10], 0.3 * r[r.size() / 10]);
}

/// Concentric circles: a cone of `levels` contours rising (or, with `pit`, falling) inwards.
ContourMap circles(int levels, bool pit, double spacing = 100.0) {
  ContourMap map;
  for (int k = 0; k < levels; ++k) {
    ContourLine line;
    line.closed = true;
    line.elevation_m = pit ? -10.0 * k : 10.0 * k;
    const double radius = (levels - k) * spacing;
    for (int a = 0; a < 180; ++a) {
      const double t = 2.0 * std::numbers::pi * a / 180.0;
      line.points.push_back({radius * std::cos(t) + 0.3 * radius * std::cos(3 * t) * 0.1, radius * std::sin(t)});
    }
    map.lines.push_back(std::move(line));
  }
  return map;
}

TEST(ContourMapToDem, EveryCellIsBracketedAndSummitsArePeaksNotPlateaus) {
  for (const bool pit : {false, true}) {
    const ContourMap map = circles(5, pit);
    const ContourMapGrid grid = contour::contour_map_grid(map, 201, 0.0);
    const Heightfield dem = contour::contour_map_to_dem(map, grid);
    const contour::GridFrame frame{grid.origin_x_m, grid.origin_y_m, grid.cell_m};
    double top = pit ? INFINITY : -INFINITY;
    for (int j = 0; j < dem.height(); ++j)
      for (int i = 0; i < dem.width(); ++i) {
        const Point p = frame.at(i, j);
        // Which ring band the cell is in (ring k has radius (5 - k) * 100, approximately).
        int inside = -1;
        for (int k = 0; k < 5; ++k)
          if (contour::contains(map.lines[static_cast<std::size_t>(k)].points, p)) inside = k;
        if (inside < 0) continue;
        const double z = dem(i, j), lo = map.lines[static_cast<std::size_t>(inside)].elevation_m;
        const double next = inside + 1 < 5 ? map.lines[static_cast<std::size_t>(inside) + 1].elevation_m : lo + (pit ? -10.0 : 10.0);
        const double margin = 1.0;  // cells a line passes through are within a cell of it
        EXPECT_GE(z, std::min(lo, next) - margin) << i << "," << j;
        EXPECT_LE(z, std::max(lo, next) + margin) << i << "," << j;
        if (inside == 4) top = pit ? std::min(top, z) : std::max(top, z);
      }
    // The innermost ring holds a rounded summit (or pit floor) beyond its level, short of the next.
    const double inner = map.lines[4].elevation_m;
    EXPECT_GT(std::abs(top - inner), 2.0) << (pit ? "pit" : "summit") << " is flat";
    EXPECT_LT(std::abs(top - inner), 10.0);
  }
}

TEST(ContourMapToDem, SameBytesWithOneAndTwoThreads) {
  const ContourMap map = io::parse_contour_map(io::read_text_file(examples + "contours/jacksboro_40m.geojson"), "jacksboro", "", false);
  const ContourMapGrid grid = contour::contour_map_grid(map, 700, 0.0);
  auto run = [&](int threads) {
    const ThreadLimit limit(threads);
    return contour::contour_map_to_dem(map, grid);
  };
  const Heightfield one = run(1), two = run(2);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_TRUE(std::equal(one.values().begin(), one.values().end(), two.values().begin()));
}

TEST(ContourMapToDem, ReadsLinesPolygonsAndSpotHeights) {
  const std::string text = R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{"ELEV":100},"geometry":{"type":"Polygon","coordinates":[[[0,0],[100,0],[100,100],[0,100],[0,0]]]}},
    {"type":"Feature","properties":{"ELEV":"90"},"geometry":{"type":"MultiLineString","coordinates":[[[-50,-50],[150,-50]],[[-50,150],[150,150]]]}},
    {"type":"Feature","properties":{"ELEV":107},"geometry":{"type":"Point","coordinates":[50,50]}}]})";
  const ContourMap without = io::parse_contour_map(text, "t", "", false);
  EXPECT_EQ(without.lines.size(), 3u);
  EXPECT_TRUE(without.lines[0].closed);
  EXPECT_EQ(without.lines[0].points.size(), 4u);
  EXPECT_FALSE(without.lines[1].closed);
  EXPECT_EQ(without.lines[1].elevation_m, 90.0);
  EXPECT_TRUE(without.spots.empty());
  const ContourMap with = io::parse_contour_map(text, "t", "ELEV", true);
  ASSERT_EQ(with.spots.size(), 1u);
  // The spot height is the summit: the DEM reaches it there and stays below it around.
  const ContourMapGrid grid = contour::contour_map_grid(with, 101, 0.0);
  const Heightfield dem = contour::contour_map_to_dem(with, grid);
  const contour::GridFrame frame{grid.origin_x_m, grid.origin_y_m, grid.cell_m};
  const int ci = static_cast<int>(std::lround(frame.column(50))), cj = static_cast<int>(std::lround(frame.row(50)));
  EXPECT_NEAR(dem(ci, cj), 107.0, 1e-3);
  float highest = -INFINITY;
  for (float v : dem.values()) highest = std::max(highest, v);
  EXPECT_NEAR(highest, 107.0, 1e-3);
  EXPECT_THROW(io::parse_contour_map(text, "t", "height", false), InputError);
}

struct BadMap {
  std::string text;
  std::string message;
};

class ContourDemCliBadInput : public ::testing::TestWithParam<BadMap> {};

TEST_P(ContourDemCliBadInput, IsRejectedWithExitTwoAMessageAndNoFile) {
  TempDir dir("contour-dem-bad");
  TempDir inputs("contour-dem-bad-inputs");
  const auto file = inputs / "contours.geojson";
  std::ofstream(file) << GetParam().text;
  expect_rejected(run_cli({"contour-dem", file.string(), "--dem", (dir / "out.tif").string()}), GetParam().message, dir.path());
}

std::string line_with(const std::string& properties) {
  return R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":)" + properties +
         R"(,"geometry":{"type":"LineString","coordinates":[[0,0],[100,50]]}}]})";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ContourDemCliBadInput,
    ::testing::Values(
        BadMap{"", "not valid JSON"}, BadMap{R"({"type":"FeatureCollection","features":[]})", "no contour lines"},
        BadMap{line_with(R"({"height":12})"), "feature 0 has no elevation attribute"},
        BadMap{line_with(R"({"elev":"NaN"})"), "is not a finite number"}, BadMap{line_with(R"({"elev":null})"), "is not a finite number"},
        BadMap{R"({"type":"Topology"})", "not a GeoJSON FeatureCollection"}, BadMap{R"({"type":7})", "not a GeoJSON FeatureCollection"},
        BadMap{R"({"type":"FeatureCollection","features":[{"properties":{"elev":1},"geometry":{"type":[]}}]})", "no contour lines"}));

TEST(ContourDemCli, WritesTheDemWithItsSidecar) {
  TempDir dir("contour-dem-out");
  const CliResult r = run_cli({"contour-dem", examples + "contours/jacksboro_40m.geojson", "--grid-from",
                               examples + "dem/jacksboro_ridge.tif", "--dem", (dir / "j.tif").string(), "--dem", (dir / "j.r32").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "j.tif.json"));
  const Heightfield dem = io::read_heightmap(dir / "j.r32");
  EXPECT_EQ(dem.width(), 110);
  EXPECT_EQ(dem.height(), 111);
}

}  // namespace
}  // namespace sansui::test

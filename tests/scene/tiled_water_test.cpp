// The rivers and lakes GeoJSON of a tiled world are the whole world's, byte for byte, and a
// river or a lake across tiles is one feature (tiled_water.hpp).
#include "scene/tiled_water.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "scene/water_geojson.hpp"
#include "water/stream_power.hpp"
#include "water/surface_water.hpp"
#include "water/tiled_test_util.hpp"
#include "water/water_test_util.hpp"

namespace sansui::scene {
namespace {

/// The whole world's texts, as the scene writes them (outputs.cpp).
TiledWaterTexts whole_texts(const Heightfield& world, const water::FlowParams& params) {
  const water::SurfaceWater water = water::surface_water(world, params);
  return {rivers_to_geojson(water.rivers, world), lakes_to_geojson(water.lakes, world)};
}

/// The texts of `world` cut into tiles of `tile` cells, worked on by one process.
TiledWaterTexts tiled_texts(const Heightfield& world, int tile, const water::FlowParams& params) {
  const TileCut cut{world.width(), world.height(), tile};
  OneProcess exchange;
  const std::vector<water::RoutedTile> tiles = water::test::routed_tiles(world, cut, params.outlets(), exchange);
  std::vector<const water::RoutedTile*> mine;
  for (const water::RoutedTile& t : tiles) mine.push_back(&t);
  return tiled_water_geojson(cut, mine, params, contour::GridFrame::of(world), exchange);
}

std::size_t features_in(const std::string& text) {
  return nlohmann::json::parse(text).at("features").size();
}

/// Where two texts first differ (a whole GeoJSON text in a failure message would bury it).
void expect_same_text(const std::string& tiled, const std::string& whole, const std::string& what) {
  if (tiled == whole) return;
  const auto at = static_cast<std::size_t>(std::mismatch(tiled.begin(), tiled.end(), whole.begin(), whole.end()).first - tiled.begin());
  const std::size_t from = at < 80 ? 0 : at - 80;
  ADD_FAILURE() << what << ": the texts differ at byte " << at << " of " << tiled.size() << " / " << whole.size() << "\ntiled: ..."
                << tiled.substr(from, 160) << "\nwhole: ..." << whole.substr(from, 160);
}

/// Both texts of every tiling equal the whole world's; returns the whole world's.
TiledWaterTexts expect_every_tiling_gives_the_whole_worlds(const Heightfield& world, const water::FlowParams& params,
                                                           const std::vector<int>& tile_sizes, const std::string& what) {
  const TiledWaterTexts whole = whole_texts(world, params);
  for (int tile : tile_sizes) {
    const TiledWaterTexts tiled = tiled_texts(world, tile, params);
    expect_same_text(tiled.rivers, whole.rivers, what + ", tiles of " + std::to_string(tile) + ": rivers");
    expect_same_text(tiled.lakes, whole.lakes, what + ", tiles of " + std::to_string(tile) + ": lakes");
  }
  return whole;
}

/// A fractal world with a few stream-power steps on it: valleys, and the pits between them.
Heightfield eroded_world() {
  Heightfield world = water::test::midpoint_terrain(257, 10.0, 5);
  world.origin_x_m = 1234.5, world.origin_y_m = -678.0;  // the features are placed in the world's plane
  water::StreamPowerParams params;
  params.time_step_yr = 5e4;
  Grid<float> eroded(257, 257, 0.0f), deposited(257, 257, 0.0f);
  for (int step = 0; step < 3; ++step) water::stream_power_step(world, params, nullptr, eroded, deposited);
  return world;
}

TEST(TiledWater, AnErodedWorldGivesTheWholeWorldsTextsOnEveryTiling) {
  const Heightfield world = eroded_world();
  for (bool sea : {false, true}) {
    water::FlowParams params;
    params.channel_area_m2 = 2e4;
    if (sea) params.sea_level_m = 0.0;
    const TiledWaterTexts whole =
        expect_every_tiling_gives_the_whole_worlds(world, params, {256, 128, 64, 40, 7}, sea ? "with sea" : "without sea");
    EXPECT_GE(features_in(whole.rivers), 30u) << "the world must have rivers across tiles";
    EXPECT_GE(features_in(whole.lakes), 4u) << "and lakes (one feature each: 13 without sea, 4 with)";
  }
}

TEST(TiledWater, FlatsTiesAndOddShapesGiveTheWholeWorldsTexts) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    Heightfield world =
        water::test::random_heights(20 + static_cast<int>(seed * 7 % 41), 17 + static_cast<int>(seed * 5 % 37), seed, seed % 2 ? 4 : 1000);
    world.cell_size_m = seed % 3 == 0 ? 3.7 : 10.0;
    water::FlowParams params;
    params.channel_area_m2 = 3.0 * world.cell_size_m * world.cell_size_m;
    if (seed % 4 == 0) params.sea_level_m = 0.5;
    expect_every_tiling_gives_the_whole_worlds(world, params, {2, 3, 5, 8}, "seed " + std::to_string(seed));
  }
}

/// A 33 x 33 world (2 x 2 tiles of 16) with one raised channel, walled on both sides, that winds
/// through the four tiles: from (4, 4) east to (28, 4), south to (28, 28), west to (4, 28) and
/// south off the map's edge. The walls drain outwards, away from it, so nothing joins it. It
/// falls 1 m a cell, 3 m at a corner so that no cell cuts the corner.
struct WindingRiver {
  Heightfield world{33, 33, 0.0f, 10.0};
  std::vector<std::pair<int, int>> path;

  WindingRiver() {
    const auto walk = [&](int x1, int y1) {
      auto [x, y] = path.back();
      while (x != x1 || y != y1) path.emplace_back(x += (x1 > x) - (x1 < x), y += (y1 > y) - (y1 < y));
    };
    path.emplace_back(4, 4);
    walk(28, 4), walk(28, 28), walk(4, 28), walk(4, 32);
    for (int y = 0; y < 33; ++y)
      for (int x = 0; x < 33; ++x) world(x, y) = static_cast<float>(std::min({x, y, 32 - x, 32 - y}));  // down to the edge
    for (const auto& [x, y] : path)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) world(x + dx, std::min(y + dy, 32)) = 2000.0f;
    float height = 1000.0f;
    for (std::size_t k = 0; k < path.size(); ++k) {
      const bool corner = k > 0 && k + 1 < path.size() && path[k + 1].first - path[k].first != path[k].first - path[k - 1].first;
      height -= k == 0 ? 0.0f : corner ? 3.0f : 1.0f;
      world(path[k].first, path[k].second) = height;
    }
  }
};

TEST(TiledWater, ARiverAcrossFourTilesIsOneFeature) {
  const WindingRiver river;
  water::FlowParams params;
  params.channel_area_m2 = 3.0 * 100.0;  // from the path's third cell on
  const TiledWaterTexts whole = expect_every_tiling_gives_the_whole_worlds(river.world, params, {16, 8, 5}, "winding river");
  const TiledWaterTexts tiled = tiled_texts(river.world, 16, params);
  // The one feature that starts on the path holds the whole path from there, through four tiles.
  const nlohmann::json rivers = nlohmann::json::parse(tiled.rivers).at("features");
  std::vector<nlohmann::json> expected;
  for (std::size_t k = 2; k < river.path.size(); ++k)
    expected.push_back(nlohmann::json::array({river.path[k].first * 10.0, -river.path[k].second * 10.0}));
  int found = 0;
  for (const nlohmann::json& feature : rivers) {
    const nlohmann::json& line = feature.at("geometry").at("coordinates");
    if (line.front() != expected.front()) continue;
    ++found;
    EXPECT_EQ(line, nlohmann::json(expected));
    EXPECT_EQ(feature.at("properties").at("strahler"), 1);
    EXPECT_EQ(feature.at("properties").at("area_m2"), 100.0 * static_cast<double>(river.path.size() - 1));
  }
  EXPECT_EQ(found, 1);
}

/// A round lake whose centre is the corner of four tiles of 16, with an island in it.
Heightfield lake_with_an_island() {
  Heightfield world(33, 33, 0.0f, 10.0);
  for (int y = 0; y < 33; ++y)
    for (int x = 0; x < 33; ++x) {
      const double r = std::hypot(x - 16.0, y - 16.0);
      world(x, y) = static_cast<float>(r < 3.0 ? 40.0 - r : r < 11.0 ? 5.0 + 0.1 * x : 30.0 - r);  // island, lake bed, rim
    }
  return world;
}

TEST(TiledWater, ALakeAcrossFourTilesIsOneFeatureWithItsIsland) {
  const Heightfield world = lake_with_an_island();
  water::FlowParams params;
  params.channel_area_m2 = 1e9;  // no rivers
  const TiledWaterTexts whole = expect_every_tiling_gives_the_whole_worlds(world, params, {16, 8, 5, 3}, "lake with an island");
  const nlohmann::json lakes = nlohmann::json::parse(whole.lakes).at("features");
  ASSERT_EQ(lakes.size(), 1u);
  ASSERT_EQ(lakes[0].at("geometry").at("coordinates").size(), 1u) << "one polygon";
  EXPECT_EQ(lakes[0].at("geometry").at("coordinates")[0].size(), 2u) << "a shell and the island's hole";
  EXPECT_EQ(features_in(whole.rivers), 0u);
}

TEST(TiledWater, WorldsWithoutRiversOrLakesGiveEmptyCollections) {
  Heightfield slope(41, 41, 0.0f, 10.0);
  for (int y = 0; y < 41; ++y)
    for (int x = 0; x < 41; ++x) slope(x, y) = static_cast<float>(100 - 2 * x - y);  // no pit: no lake
  water::FlowParams params;
  params.channel_area_m2 = 2000.0;
  TiledWaterTexts whole = expect_every_tiling_gives_the_whole_worlds(slope, params, {20, 8, 3}, "slope");
  EXPECT_GT(features_in(whole.rivers), 0u);
  EXPECT_EQ(features_in(whole.lakes), 0u);
  params.channel_area_m2 = 1e9;
  whole = expect_every_tiling_gives_the_whole_worlds(slope, params, {20, 8, 3}, "slope, no channel");
  EXPECT_EQ(features_in(whole.rivers), 0u);
}

}  // namespace
}  // namespace sansui::scene

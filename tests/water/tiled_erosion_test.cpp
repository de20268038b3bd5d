// Erosion of a tiled world gives the whole world's bytes (tiled_erosion.hpp).
#include "water/tiled_erosion.hpp"

#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "water_test_util.hpp"

namespace sansui::water {
namespace {

/// The own cells of tile t of `world`.
Heightfield own_part(const Heightfield& world, const TileCut& cut, int t) {
  return copy_of(world.view(cut.owned(t)));
}

/// Counts the cells where the tiles' heights or maps differ from the whole world's.
std::int64_t cells_differing(const TileCut& cut, const std::vector<ErodingTile>& tiles, const Heightfield& heights,
                             const Grid<float>& eroded, const Grid<float>& deposited, const std::string& what) {
  std::int64_t differing = 0;
  for (const ErodingTile& t : tiles) {
    const Rect own = cut.owned(t.tile), halo = cut.haloed(t.tile);
    for (int y = own.y0; y < own.y1; ++y)
      for (int x = own.x0; x < own.x1; ++x) {
        const float h = t.flow.heights(x - halo.x0, y - halo.y0);
        const bool same = h == heights(x, y) && t.eroded_m(x - own.x0, y - own.y0) == eroded(x, y) &&
                          t.deposited_m(x - own.x0, y - own.y0) == deposited(x, y);
        if (!same && differing++ < 3)
          ADD_FAILURE() << what << ": cell " << x << "," << y << " height " << h << " / " << heights(x, y) << ", eroded "
                        << t.eroded_m(x - own.x0, y - own.y0) << " / " << eroded(x, y);
      }
  }
  return differing;
}

TEST(TiledErosion, StreamPowerStepsGiveTheWholeWorldsBytesOnEveryTiling) {
  const Heightfield world = test::midpoint_terrain(129, 10.0, 7);
  StreamPowerParams params;
  params.diffusivity_m2_per_yr = 0.5;
  params.time_step_yr = 5e4;
  for (bool sea : {false, true}) {
    params.sea_level_m = sea ? std::optional<double>(0.0) : std::nullopt;
    Heightfield heights = world;
    Grid<float> eroded(129, 129, 0.0f), deposited(129, 129, 0.0f);
    StreamPowerWorkspace workspace;
    for (int step = 0; step < 3; ++step) stream_power_step(heights, params, nullptr, eroded, deposited, workspace);
    ASSERT_NE(test::hash_of(heights), test::hash_of(world)) << "the steps must change the land";
    ASSERT_NE(test::hash_of(deposited), test::hash_of(Grid<float>(129, 129, 0.0f))) << "and deposit somewhere";
    for (int tile : {128, 64, 32, 8, 3}) {
      const TileCut cut{129, 129, tile};
      OneProcess exchange;
      std::vector<ErodingTile> tiles = eroding_tiles(cut, 10.0, exchange, [&](int t) { return own_part(world, cut, t); });
      for (int step = 0; step < 3; ++step) tiled_stream_power_step(cut, tiles, params, exchange);
      EXPECT_EQ(cells_differing(cut, tiles, heights, eroded, deposited, "tile " + std::to_string(tile)), 0)
          << "tile " << tile << (sea ? " with sea" : "");
    }
  }
}

/// The default erosion chain (stage mature: response time, steps, droplets, kept detail) on a
/// tiled world against erode() on the whole.
void expect_tiled_chain_equals_whole(const Heightfield& world, const std::vector<int>& tile_sizes, std::optional<double> sea,
                                     ErosionChainParams chain = {}, int model = default_erosion_model) {
  chain.fluvial.sea_level_m = sea;
  chain.fluvial.steps = 4;
  const ErosionResult whole = erode(world, chain, ErosionStage::mature, quiet_context(), model);
  ASSERT_NE(test::hash_of(whole.heights), test::hash_of(world));
  for (int tile : tile_sizes) {
    const TileCut cut{world.width(), world.height(), tile};
    OneProcess exchange;
    std::vector<ErodingTile> tiles = eroding_tiles(cut, world.cell_size_m, exchange, [&](int t) { return own_part(world, cut, t); });
    tiled_erode(cut, tiles, chain, ErosionStage::mature, exchange, quiet_context(), model);
    EXPECT_EQ(cells_differing(cut, tiles, whole.heights, whole.eroded_m, whole.deposited_m, "tile " + std::to_string(tile)), 0)
        << "tile " << tile << (sea ? " with sea" : "") << ", model " << model;
  }
}

TEST(TiledErosion, TheDefaultChainGivesTheWholeWorldsBytesOnEveryTiling) {
  const Heightfield world = test::midpoint_terrain(257, 10.0, 11);
  expect_tiled_chain_equals_whole(world, {128, 64, 40, 7}, std::nullopt);
  expect_tiled_chain_equals_whole(world, {64}, 0.0);
  expect_tiled_chain_equals_whole(world, {64, 7}, 0.0, {}, 2);  // recipes of versions 2 to 5
  expect_tiled_chain_equals_whole(world, {64, 7}, 0.0, {}, 3);  // version 6
}

TEST(TiledErosion, LandThatDoesNotErodeKeepsItsDropletsAndDetailOnBoth) {
  // Erodibility 0: the response time is infinite and routes nothing, so the first step has no
  // routing to take (it once took an empty one: "internal error"); droplets still run.
  ErosionChainParams chain;
  chain.fluvial.erodibility = 0.0;
  expect_tiled_chain_equals_whole(test::midpoint_terrain(129, 10.0, 2), {64, 40}, 0.0, chain);
}

TEST(TiledErosion, ReportsItsProgressAsTheWholeChainDoes) {
  // One order, one progress: "erosion", only forward, to 1, part by part.
  const Heightfield world = test::midpoint_terrain(129, 10.0, 5);
  const TileCut cut{129, 129, 64};
  OneProcess exchange;
  std::vector<ErodingTile> tiles = eroding_tiles(cut, 10.0, exchange, [&](int t) { return own_part(world, cut, t); });
  std::vector<double> fractions;
  Context context;
  context.on_progress = [&](std::string_view stage, double fraction) {
    EXPECT_EQ(stage, "erosion");
    fractions.push_back(fraction);
  };
  ErosionChainParams chain;
  chain.fluvial.steps = 5;
  tiled_erode(cut, tiles, chain, ErosionStage::mature, exchange, context);
  ASSERT_GE(fractions.size(), 6u);  // a report a step, and the last
  for (std::size_t k = 1; k < fractions.size(); ++k) EXPECT_GE(fractions[k], fractions[k - 1]) << k;
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
}

TEST(TiledErosion, ThermalErosionIsRefusedWithItsDefaultNamed) {
  const Heightfield world = test::midpoint_terrain(65, 10.0, 1);
  const TileCut cut{65, 65, 32};
  OneProcess exchange;
  std::vector<ErodingTile> tiles = eroding_tiles(cut, 10.0, exchange, [&](int t) { return own_part(world, cut, t); });
  ErosionChainParams chain;
  chain.thermal.iterations = 5;
  try {
    tiled_erode(cut, tiles, chain, std::nullopt, exchange);
    FAIL() << "thermal erosion ran on tiles";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("thermal iterations = 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sansui::water

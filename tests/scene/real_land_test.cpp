// Real land by default (issue 27): what `sansui terrain` and the main job make with no options is
// eroded, drained land with a coast, measured against real elevation models (water/landform.hpp):
// channels gentler than hillslopes, the spectral exponent of real land, stages that wear the land
// down in order, erosion that scales with the grid and respects a contour mountain's base level.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_runner.hpp"
#include "io/heightmap_io.hpp"
#include "scene/pipeline.hpp"
#include "scene/recipe_file.hpp"
#include "terrain/midpoint.hpp"
#include "test_util.hpp"
#include "tests/test_paths.hpp"
#include "water/droplets.hpp"
#include "water/landform.hpp"

namespace sansui::scene {
namespace {

/// The recipe of `sansui terrain --size SIZE --seed SEED` (eroded at `stage`), heights only.
Recipe default_terrain(int size, std::uint64_t seed, terrain::Stage stage = terrain::Stage::mature) {
  Recipe recipe = default_recipe(SourceKind::midpoint);
  recipe.world.size = size;
  recipe.midpoint.seed = seed;
  recipe.shape = {default_erode_step()};
  recipe.shape[0].stage.stage = stage;
  return recipe;
}

water::LandformMeasures measures_of(const Recipe& recipe) {
  return water::measure_landform(recipe_heights(recipe), 0.0);
}

// Real land: the median slope of channels (drainage area at least 1 % of the map) over that of
// hillslopes (at most 2 cells) is 0.26-0.54, the spectral exponent 1.6-3.6. Raw midpoint terrain
// measures 0.6-0.9 and, at H 0.8, up to 3.75.
void expect_real_land(const water::LandformMeasures& m, const std::string& what) {
  EXPECT_GE(m.channel_ratio, 0.26) << what;
  EXPECT_LE(m.channel_ratio, 0.54) << what;
  EXPECT_GE(m.spectral_beta, 1.6) << what;
  EXPECT_LE(m.spectral_beta, 3.6) << what;
}

TEST(RealLand, TheDefaultTerrainDrainsLikeRealLandOnSeveralSeedsAndSizes) {
  // Seeds 1-20 at 1025 measure a ratio of 0.29-0.48 and a beta of 3.19-3.57 (bench/real_land.sh);
  // at 513, seed 3 measures a beta of 3.65, the only one of twenty outside (docs/erosion.md).
  for (const std::uint64_t seed : {1u, 2u, 5u}) {
    const water::LandformMeasures m = measures_of(default_terrain(513, seed));
    expect_real_land(m, "513, seed " + std::to_string(seed));
  }
  expect_real_land(measures_of(default_terrain(1025, 20)), "1025, seed 20");
}

TEST(RealLand, TheRawTerrainDoesNot) {
  Recipe recipe = default_terrain(513, 1);
  recipe.shape.clear();
  EXPECT_GT(measures_of(recipe).channel_ratio, 0.6);
}

TEST(RealLand, TheMainJobDrainsLikeRealLand) {
  LoadedRecipe loaded = load_recipe(std::string(sansui::test::source_dir) + "/examples/scenes/gallery/tropical-coast.toml");
  // Version 4's defaults of the land are today's: version 5 changed only the names of local CRSs.
  ASSERT_GE(loaded.recipe.version, 4);
  expect_real_land(measures_of(loaded.recipe), "the main job");
}

TEST(RealLand, StagesWearTheLandDownInOrder) {
  // Relief (the highest point above the sea) and mean slope fall from original to peneplain.
  const terrain::Stage stages[] = {terrain::Stage::original, terrain::Stage::young, terrain::Stage::mature, terrain::Stage::old,
                                   terrain::Stage::peneplain};
  for (const std::uint64_t seed : {1u, 5u}) {
    double relief = INFINITY, slope = INFINITY;
    for (const terrain::Stage stage : stages) {
      const water::LandformMeasures m = measures_of(default_terrain(513, seed, stage));
      const std::string what = "seed " + std::to_string(seed) + ", " + std::string(terrain::stage_name(stage));
      EXPECT_LT(m.relief_m, relief) << what;
      EXPECT_LT(m.mean_slope, slope) << what;
      relief = m.relief_m, slope = m.mean_slope;
    }
  }
}

TEST(RealLand, EverySeedHasLandAndSea) {
  // The default world: 70 % of it above sea level, whatever the seed (the paper's sea level at
  // the generator's zero gives anything from none to all; seed 7 was 99.7 % sea).
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Recipe recipe = default_terrain(257, seed);
    recipe.shape.clear();
    const double land = water::measure_landform(recipe_heights(recipe), 0.0).land_fraction;
    EXPECT_GE(land, 0.65) << "seed " << seed;
    EXPECT_LE(land, 0.75) << "seed " << seed;
  }
  for (const std::uint64_t seed : {7u, 8u}) {
    const double land = measures_of(default_terrain(513, seed)).land_fraction;  // eroded: a little lower
    EXPECT_GE(land, 0.6) << "seed " << seed;
    EXPECT_LE(land, 0.75) << "seed " << seed;
  }
}

TEST(RealLand, TheLandFractionIsTheWholeWorldsSoTilesAgree) {
  terrain::MidpointParams params;
  params.seed = 9;
  const float offset = terrain::sea_level_offset(params, 11);
  // Every tile and preview of the same world shifts by the same height.
  EXPECT_EQ(offset, terrain::sea_level_offset(params, 11));
  params.paper_sea_level = true;
  EXPECT_EQ(terrain::sea_level_offset(params, 11), 0.0f);
}

/// FNV-1a of seed 7's default 129^2 terrain in a recipe of `version`: raw, then eroded.
std::pair<std::uint64_t, std::uint64_t> seed_7_hashes(int version, std::optional<double> sigma_m = std::nullopt) {
  Recipe eroded = default_terrain(129, 7);
  eroded.version = version;
  if (sigma_m) eroded.midpoint.sigma_m = *sigma_m;
  Recipe raw = eroded;
  raw.shape.clear();
  const Heightfield raw_heights = recipe_heights(raw), eroded_heights = recipe_heights(eroded);
  return {test::fnv1a(raw_heights.values()), test::fnv1a(eroded_heights.values())};
}

TEST(RealLand, SeedsGiveTheSameTerrainFromNowOn) {
  // Version 2's and 3's terrains (a fixed sigma of 250 m): a change of these bytes must be in
  // CHANGELOG.md.
  const auto [raw3, eroded3] = seed_7_hashes(3, 250.0);
  EXPECT_EQ(raw3, 13066105396010205814ull) << "the raw default terrain of seed 7";
  EXPECT_EQ(eroded3, 15247307520127801712ull) << "the eroded default terrain of seed 7";
  // Version 4's: the relief follows the world's extent (1,280 m here); the default world of
  // 1025 samples 10 m apart keeps version 3's. Version 5 kept them.
  const auto [raw5, eroded5] = seed_7_hashes(5);
  EXPECT_EQ(raw5, 443959105598564870ull) << "the raw default terrain of seed 7, version 4";
  EXPECT_EQ(eroded5, 8582509393672322976ull) << "the eroded default terrain of seed 7, version 4";
  // Version 6's: erosion model 3 (the same raw terrain).
  const auto [raw6, eroded6] = seed_7_hashes(6);
  EXPECT_EQ(raw6, 443959105598564870ull) << "the raw default terrain of seed 7, version 6";
  EXPECT_EQ(eroded6, 2826293380295577890ull) << "the eroded default terrain of seed 7, version 6";
  // Version 7's: erosion model 4, with land past the map's edges (the same raw terrain).
  const auto [raw7, eroded7] = seed_7_hashes(7);
  EXPECT_EQ(raw7, 443959105598564870ull) << "the raw default terrain of seed 7, version 7";
  EXPECT_EQ(eroded7, 8941701663956873188ull) << "the eroded default terrain of seed 7, version 7";
}

TEST(RealLand, NoEdgeStandsAsARim) {
  // Eroded inside its edges alone (erosion model 3, version 6), each edge is a divide: a strip
  // along it erodes less and ends in a scarp (seed 1: D 0.19 at its north edge). With land past
  // the edges (model 4) the strips' slopes are the land's inside them (D 0.03-0.09 on seeds 1-4
  // at 1025^2; the raw terrain's 0.01-0.08).
  for (const std::uint64_t seed : {1u, 3u})
    EXPECT_LE(water::edge_slope_distance(recipe_heights(default_terrain(1025, seed)), 0.0), 0.12) << "seed " << seed;
  Recipe version_6 = default_terrain(1025, 1);
  version_6.version = 6;
  EXPECT_GT(water::edge_slope_distance(recipe_heights(version_6), 0.0), 0.15) << "the measure sees the rims of version 6";
}

TEST(RealLand, DropletsPerCellAreTheSameOnEveryGrid) {
  const ShapeStep step = default_erode_step();
  EXPECT_FALSE(step.erosion.droplets.droplets.has_value());
  for (const std::size_t side : {65u, 1025u, 8193u}) {
    const std::size_t cells = side * side;
    EXPECT_NEAR(static_cast<double>(water::droplet_count(step.erosion.droplets, cells)),
                step.erosion.droplets.droplets_per_cell * static_cast<double>(cells), 0.5)
        << side;
  }
}

TEST(RealLand, VersionOneRecipesKeepTheirDefaults) {
  const LoadedRecipe v1 = parse_recipe_toml("sansui_recipe = 1\nsource = \"midpoint\"\n[[shape]]\nstep = \"erode\"\n", "v1.toml", ".");
  EXPECT_EQ(v1.recipe.version, 1);
  EXPECT_TRUE(v1.recipe.midpoint.paper_sea_level);
  EXPECT_EQ(v1.recipe.midpoint.hurst, 0.8);
  EXPECT_EQ(v1.recipe.midpoint.sigma_m, 400.0);
  const water::ErosionChainParams& chain = v1.recipe.shape.at(0).erosion;
  EXPECT_EQ(chain.fluvial.uplift_m_per_yr, 1e-4);
  EXPECT_EQ(chain.fluvial.diffusivity_m2_per_yr, 0.01);
  EXPECT_EQ(chain.fluvial.steps, 10);
  EXPECT_EQ(chain.thermal.iterations, 20);
  EXPECT_EQ(chain.droplets.droplets, 200000);
  EXPECT_EQ(chain.keep_detail, 0.0);
  // And written out again, it stays a version 1 recipe.
  EXPECT_NE(recipe_to_toml(v1.recipe).find("sansui_recipe = 1\n"), std::string::npos);
}

/// A cone of about 60 m grown from one circular contour, on 81 x 81 samples.
std::string cone_seed(const test::TempDir& dir) {
  std::ostringstream ring;
  for (int i = 0; i <= 64; ++i) {
    const double a = 2.0 * M_PI * (i % 64) / 64.0;
    ring << (i ? "," : "") << "[" << 200.0 * std::cos(a) << "," << 200.0 * std::sin(a) << "]";
  }
  std::string file = (dir / "cone.geojson").string();  // not const: returned by move
  std::ofstream(file) << R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},"geometry":{"type":"Polygon",)"
                      << R"("coordinates":[[)" << ring.str() << "]]}}]}";
  return file;
}

Heightfield contour_dem(const std::vector<std::string>& extra, const test::TempDir& dir, const std::string& name) {
  const std::string out = (dir / name).string();
  std::vector<std::string> args{"contour", cone_seed(dir), "--dem-size", "81", "--dem", out};
  args.insert(args.end(), extra.begin(), extra.end());
  const test::CliResult run = test::run_cli(args);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return io::read_heightmap(out);
}

double highest(const Heightfield& h) {
  return *std::max_element(h.values().begin(), h.values().end());
}

TEST(RealLand, AYoungContourMountainKeepsNinetyPercentOfItsRelief) {
  const test::TempDir dir("real-land-cone");
  for (const std::string surround : {"foothills", "flat"}) {
    const Heightfield before = contour_dem({"--dem-surround", surround}, dir, "before-" + surround + ".r32");
    const Heightfield after =
        contour_dem({"--dem-surround", surround, "--erode", "--erode-stage", "young"}, dir, "after-" + surround + ".r32");
    // Relief above the seed contour's level (0 m). 85 %, issue 48's bar for a contour mountain:
    // erosion model 2 kept 93 % with foothills, but only because it put the summit's whole fine
    // roughness back on top of what the erosion had left of it; model 3 keeps 87 % (flat: 92 %).
    EXPECT_GE(highest(after), 0.85 * highest(before)) << surround;
    EXPECT_LE(highest(after), highest(before) + 1e-3) << surround;
  }
}

TEST(RealLand, AFlatPlainIsBaseLevelNotABasin) {
  // The plain around the mountain sits at its base (0 m): water leaves there, and sediment does
  // not fill it (it once gained about 110 m, and islands lost most of their height).
  const test::TempDir dir("real-land-plain");
  const Heightfield before = contour_dem({"--dem-surround", "flat"}, dir, "before.r32");
  const Heightfield after = contour_dem({"--dem-surround", "flat", "--erode", "--erode-stage", "mature"}, dir, "after.r32");
  // Droplets slowing at the foot leave small fans on the plain next to it (a few centimetres on
  // average, under a metre at most); nothing more.
  double rise = 0.0, cells = 0.0;
  for (std::size_t i = 0; i < before.size(); ++i)
    if (before.values()[i] <= 0.0f) {
      ASSERT_LT(after.values()[i] - before.values()[i], 2.0f) << "plain cell " << i;
      ASSERT_GE(after.values()[i], before.values()[i]) << "plain cell " << i;
      rise += after.values()[i] - before.values()[i], cells += 1.0;
    }
  EXPECT_LT(rise / cells, 0.1);
  EXPECT_GE(highest(after), 0.35 * highest(before));
}

TEST(RealLand, ASeedFromADemTakesABaseBelowItsLevelWithoutZ0) {
  const test::TempDir dir("real-land-from-dem");
  const std::string dem = (dir / "dem.r32").string();
  ASSERT_EQ(test::run_cli({"terrain", "--size", "129", "--seed", "5", "-o", dem}).exit_code, 0);
  const test::CliResult run =
      test::run_cli({"contour", "--from-dem", dem, "--level", "60", "--base", "54", "--dem-size", "65", "--dem", (dir / "m.r32").string()});
  EXPECT_EQ(run.exit_code, 0) << run.err;
}

}  // namespace
}  // namespace sansui::scene

namespace sansui::scene {
namespace {

/// The median slope of the land (above 0 m), by central differences. [Units: deg]
double median_land_slope_deg(const Heightfield& h) {
  std::vector<double> slopes;
  for (int y = 1; y + 1 < h.height(); ++y)
    for (int x = 1; x + 1 < h.width(); ++x) {
      if (h(x, y) <= 0.0f) continue;
      const double dx = (h(x + 1, y) - h(x - 1, y)) / (2.0 * h.cell_size_m), dy = (h(x, y + 1) - h(x, y - 1)) / (2.0 * h.cell_size_m);
      slopes.push_back(std::atan(std::hypot(dx, dy)) * 180.0 / std::numbers::pi);
    }
  std::nth_element(slopes.begin(), slopes.begin() + static_cast<std::ptrdiff_t>(slopes.size() / 2), slopes.end());
  return slopes[slopes.size() / 2];
}

// The default relief follows the world's extent, so the default terrain is land at every cell
// size: its median slope stays within 5-30 degrees, soil-mantled hills to threshold slopes
// (Montgomery and Brandon 2002), falling with coarser cells as real DEMs' slopes do. With a
// fixed sigma, 2 m cells gave a median slope of 54 degrees (a field of spikes).
TEST(RealLand, TheDefaultReliefFollowsTheCellSize) {
  double previous = 90.0;
  for (double cell : {1.0, 10.0, 100.0}) {
    Recipe recipe = default_terrain(257, 3);
    recipe.world.cell_m = cell;
    const double median = median_land_slope_deg(recipe_heights(recipe));
    EXPECT_GE(median, 5.0) << cell << " m cells";
    EXPECT_LE(median, 30.0) << cell << " m cells";
    EXPECT_LT(median, previous) << cell << " m cells";
    previous = median;
  }
}

}  // namespace
}  // namespace sansui::scene

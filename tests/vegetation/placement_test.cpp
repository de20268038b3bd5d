// Plant placement: determinism (seeds, tiles, threads), the rules (sea, tree line, slope, bands,
// water's edge, season), density on flat land, progress and bad parameters.
#include "vegetation/placement.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <string>
#include <tuple>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "core/error.hpp"
#include "terrain/midpoint.hpp"
#include "tests/test_util.hpp"

namespace sansui::vegetation {
namespace {

using ::testing::HasSubstr;

/// A 257 x 257 fractal terrain 1280 m across, from -79 m to 168 m: sea, forest, land above the
/// tree line of mixed_rules(), and slopes from flat to steep.
Heightfield rough_terrain(double origin_x_m = 0.0, double origin_y_m = 0.0) {
  terrain::MidpointParams params;
  params.seed = 1;
  params.sigma_m = 60.0;
  Heightfield heights = terrain::generate_midpoint(params, 257);
  heights.cell_size_m = 5.0;
  heights.origin_x_m = origin_x_m;
  heights.origin_y_m = origin_y_m;
  return heights;
}

Heightfield flat_land(int size, double cell_m, float height_m) {
  return Heightfield(size, size, height_m, cell_m);
}

PlacementRules mixed_rules() {
  PlacementRules rules;
  rules.tree_density = 0.5;
  rules.ground_density = 0.3;
  rules.sea_level_m = 0.0;
  rules.tree_line_m = 120.0;
  rules.water_edge_m = 15.0;
  rules.species = {{"oak", 0.0, 0.6, 2.0},
                   {"pine", 0.4, 1.0, 1.0},
                   {"date_palm", 0.0, 1.0, 5.0, true},
                   {"short_grass", 0.0, 1.0, 1.0},
                   {"moss", 0.5, 1.0, 1.0, false, true}};
  return rules;
}

VegetationParams spaced(double spacing_m, double ground_spacing_m) {
  VegetationParams params;
  params.seed = 77;
  params.spacing_m = spacing_m;
  params.ground_spacing_m = ground_spacing_m;
  return params;
}

std::uint64_t hash_of(const std::vector<Instance>& instances) {
  return test::fnv1a(std::span<const Instance>(instances));
}
std::uint64_t hash_of(const Placement& placement) {
  return hash_of(placement.trees) ^ (hash_of(placement.ground) * 31);
}

std::uint16_t species_index_for_test(std::string_view name) {
  const auto& library = species_library();
  const auto found = std::ranges::find_if(library, [&](const Species& s) { return s.name == name; });
  EXPECT_NE(found, library.end()) << name;
  return static_cast<std::uint16_t>(found - library.begin());
}

bool same_bytes(const Instance& a, const Instance& b) {
  return std::memcmp(&a, &b, sizeof(Instance)) == 0;
}
bool by_position(const Instance& a, const Instance& b) {
  return std::tie(a.y_m, a.x_m, a.species) < std::tie(b.y_m, b.x_m, b.species);
}

/// The ground under a world point, computed here in the plainest way, for checking.
struct Probe {
  double height_m = 0.0, slope_deg = 0.0;
};
Probe probe(const Heightfield& heights, double x_m, double y_m) {
  const double fx = (x_m - heights.origin_x_m) / heights.cell_size_m, fy = (y_m - heights.origin_y_m) / heights.cell_size_m;
  const int column = std::clamp(static_cast<int>(std::floor(fx)), 0, heights.width() - 2);
  const int row = std::clamp(static_cast<int>(std::floor(fy)), 0, heights.height() - 2);
  const double ax = fx - column, ay = fy - row;
  const double h00 = heights(column, row), h10 = heights(column + 1, row), h01 = heights(column, row + 1),
               h11 = heights(column + 1, row + 1);
  const double dx = ((h10 - h00) * (1 - ay) + (h11 - h01) * ay) / heights.cell_size_m;
  const double dy = ((h01 - h00) * (1 - ax) + (h11 - h10) * ax) / heights.cell_size_m;
  return {(h00 * (1 - ax) + h10 * ax) * (1 - ay) + (h01 * (1 - ax) + h11 * ax) * ay,
          std::atan(std::sqrt(dx * dx + dy * dy)) * 180.0 / std::numbers::pi};
}

/// The gentlest slope around a point: a plant's stored float position may lie a hair across a
/// sample line from where it was placed, where the bilinear gradient jumps.
double gentlest_slope_deg(const Heightfield& heights, double x_m, double y_m) {
  double slope = 90.0;
  for (double dx : {-1e-3, 0.0, 1e-3})
    for (double dy : {-1e-3, 0.0, 1e-3}) slope = std::min(slope, probe(heights, x_m + dx, y_m + dy).slope_deg);
  return slope;
}

TEST(Placement, SameSeedGivesTheSameBytes) {
  const Heightfield heights = rough_terrain();
  const Placement a = place_plants(heights, spaced(7.0, 1.9), mixed_rules());
  const Placement b = place_plants(heights, spaced(7.0, 1.9), mixed_rules());
  ASSERT_GT(a.trees.size(), 100u);
  ASSERT_GT(a.ground.size(), 1000u);
  EXPECT_EQ(hash_of(a), hash_of(b));
}

TEST(Placement, DifferentSeedsGiveDifferentPlants) {
  const Heightfield heights = rough_terrain();
  VegetationParams other = spaced(7.0, 1.9);
  other.seed = 78;
  const Placement a = place_plants(heights, spaced(7.0, 1.9), mixed_rules());
  const Placement b = place_plants(heights, other, mixed_rules());
  EXPECT_NE(hash_of(a.trees), hash_of(b.trees));
  EXPECT_NE(hash_of(a.ground), hash_of(b.ground));
}

TEST(Placement, GoldenPositionsOnFlatLand) {
  // Positions depend only on the seed and the grid: if this changes, placements saved by earlier
  // versions cannot be rebuilt.
  // Without clumping the grid is the one of earlier versions, cell for cell.
  PlacementRules rules;
  rules.species = {{"oak"}};
  VegetationParams even = spaced(8.0, 2.0);
  even.clumping = 0.0;
  const Placement placement = place_plants(flat_land(33, 2.0, 10.0f), even, rules);
  std::vector<float> positions;
  for (const Instance& tree : placement.trees) positions.insert(positions.end(), {tree.x_m, tree.y_m});
  EXPECT_EQ(placement.trees.size(), 24u);
  EXPECT_EQ(test::fnv1a(std::span<const float>(positions)), 16750191600603435819u);
}

/// A world cut into 2 x 2 tiles: cell size, origin in cells (crossing zero, so that tile and
/// world coordinates have different magnitudes), tree and ground spacing.
struct TileCase {
  double cell_m;
  int origin_x_cells, origin_y_cells;
  double spacing_m, ground_spacing_m;
};

class PlacementTiles : public ::testing::TestWithParam<TileCase> {};

TEST_P(PlacementTiles, HoldExactlyTheWholeWorldsPlants) {
  // Tiles of 129 x 129 samples that share their border samples; their origins are computed the
  // way a user would, origin + k * cell, which need not be exact for cells like 0.3 m.
  const TileCase c = GetParam();
  Heightfield world = rough_terrain(c.origin_x_cells * c.cell_m, c.origin_y_cells * c.cell_m);
  for (float& h : world.values()) h = static_cast<float>(h * c.cell_m / world.cell_size_m);  // same slopes
  world.cell_size_m = c.cell_m;
  const VegetationParams params = spaced(c.spacing_m, c.ground_spacing_m);
  const Placement whole = place_plants(world, params, mixed_rules());
  // (The smallest world, 77 m across, lies partly in a clearing of the density field.)
  ASSERT_GT(whole.trees.size(), 50u);

  Placement tiled;
  for (int ty = 0; ty < 2; ++ty)
    for (int tx = 0; tx < 2; ++tx) {
      Heightfield tile = copy_of(world.view(Rect{tx * 128, ty * 128, tx * 128 + 129, ty * 128 + 129}));
      tile.cell_size_m = world.cell_size_m;
      tile.origin_x_m = world.origin_x_m + tx * 128 * world.cell_size_m;
      tile.origin_y_m = world.origin_y_m + ty * 128 * world.cell_size_m;
      const Placement part = place_plants(tile, params, mixed_rules());
      tiled.trees.insert(tiled.trees.end(), part.trees.begin(), part.trees.end());
      tiled.ground.insert(tiled.ground.end(), part.ground.begin(), part.ground.end());
    }
  for (auto* layer : {&tiled.trees, &tiled.ground}) std::ranges::sort(*layer, by_position);
  Placement sorted = whole;
  for (auto* layer : {&sorted.trees, &sorted.ground}) std::ranges::sort(*layer, by_position);
  ASSERT_EQ(tiled.trees.size(), sorted.trees.size());
  ASSERT_EQ(tiled.ground.size(), sorted.ground.size());
  EXPECT_TRUE(std::ranges::equal(tiled.trees, sorted.trees, same_bytes));
  EXPECT_TRUE(std::ranges::equal(tiled.ground, sorted.ground, same_bytes));
}

INSTANTIATE_TEST_SUITE_P(Worlds, PlacementTiles,
                         ::testing::Values(TileCase{5.0, -128, 8, 7.0, 1.3}, TileCase{0.3, -64, -200, 1.1, 0.37},
                                           TileCase{30.0, 1000, -129, 100.0, 20.0}));

TEST(Placement, SameWithOneAndTwoThreads) {
  const Heightfield heights = rough_terrain();
  Placement one, two;
  tbb::task_arena(1).execute([&] { one = place_plants(heights, spaced(7.0, 1.3), mixed_rules()); });
  tbb::task_arena(2).execute([&] { two = place_plants(heights, spaced(7.0, 1.3), mixed_rules()); });
  EXPECT_EQ(hash_of(one), hash_of(two));
  EXPECT_EQ(one.trees.size(), two.trees.size());
}

TEST(Placement, InstancesAreInGridOrder) {
  const Placement placement = place_plants(rough_terrain(), spaced(7.0, 1.3), mixed_rules());
  for (const auto* layer : {&placement.trees, &placement.ground}) {
    const double spacing = layer == &placement.trees ? 7.0 : 1.3;
    // The grid cells a stored float coordinate may have come from: it may have rounded onto an edge.
    auto cells = [&](float v) { return std::pair{std::floor((v - 1e-3) / spacing), std::floor((v + 1e-3) / spacing)}; };
    for (std::size_t i = 1; i < layer->size(); ++i) {
      const Instance &a = (*layer)[i - 1], &b = (*layer)[i];
      const auto row_a = cells(a.y_m), row_b = cells(b.y_m);
      ASSERT_LE(row_a.first, row_b.second) << i;
      if (row_a.first == row_a.second && row_a == row_b) {
        ASSERT_LE(cells(a.x_m).first, cells(b.x_m).second) << i;
      }
    }
  }
}

TEST(Placement, NoPlantUnderTheSeaAboveTheTreeLineOrOnTooSteepASlope) {
  const Heightfield heights = rough_terrain(100.0, -50.0);
  const PlacementRules rules = mixed_rules();
  const VegetationParams params = spaced(4.0, 1.5);
  const Placement placement = place_plants(heights, params, rules);
  // The terrain has every kind of ground, so the rules are really at work.
  double steepest = 0.0, lowest = 1e9, highest = -1e9;
  for (int y = 0; y + 1 < heights.height(); ++y)
    for (int x = 0; x + 1 < heights.width(); ++x) {
      const Probe p = probe(heights, 100.0 + (x + 0.5) * heights.cell_size_m, -50.0 + (y + 0.5) * heights.cell_size_m);
      steepest = std::max(steepest, p.slope_deg), lowest = std::min(lowest, p.height_m), highest = std::max(highest, p.height_m);
    }
  ASSERT_GT(steepest, 60.0);
  ASSERT_LT(lowest, rules.sea_level_m);
  ASSERT_GT(highest, rules.tree_line_m);

  const auto& library = species_library();
  for (const auto* layer : {&placement.trees, &placement.ground}) {
    ASSERT_FALSE(layer->empty());
    for (const Instance& plant : *layer) {
      const Species& species = library.at(plant.species);
      EXPECT_EQ(species.layer, layer == &placement.trees ? Layer::tree : Layer::ground) << species.name;
      EXPECT_GT(plant.height_m, rules.sea_level_m);
      EXPECT_LE(plant.height_m, rules.tree_line_m);
      const Probe ground = probe(heights, plant.x_m, plant.y_m);
      EXPECT_NEAR(plant.height_m, ground.height_m, 0.01 + 1e-3 * std::tan(ground.slope_deg * std::numbers::pi / 180.0));
      EXPECT_LE(gentlest_slope_deg(heights, plant.x_m, plant.y_m), species.max_slope_deg + 1e-6)
          << species.name << " at " << plant.x_m << ", " << plant.y_m;
      // Inside the heightfield (<= at the far edge: the float position may round onto it).
      EXPECT_GE(plant.x_m, heights.origin_x_m);
      EXPECT_LE(plant.x_m, heights.origin_x_m + 256 * heights.cell_size_m);
      EXPECT_GE(plant.y_m, heights.origin_y_m);
      EXPECT_LE(plant.y_m, heights.origin_y_m + 256 * heights.cell_size_m);
      // Trees: their age's size, the species' spread at half strength, stunted by up to 40 %
      // toward the tree line; ground plants: the species' spread.
      const bool tree = layer == &placement.trees;
      const double low = tree ? size_of_age(0.0) * (1.0 - 0.5 * species.height_jitter) * 0.6 : 1.0 - species.height_jitter;
      const double high = tree ? size_of_age(1.0) * (1.0 + 0.5 * species.height_jitter) : 1.0 + species.height_jitter;
      EXPECT_GE(plant.scale, low * params.scale - 1e-6);
      EXPECT_LE(plant.scale, high * params.scale + 1e-6);
      EXPECT_GE(plant.rotation_rad, 0.0f);
      EXPECT_LT(plant.rotation_rad, static_cast<float>(2.0 * std::numbers::pi));
      EXPECT_LT(plant.variant, variants_per_species);
    }
  }
}

TEST(Placement, DensityOnFlatLandIsTheRulesFigure) {
  // 1024 m x 1024 m of flat land inside the forest band.
  const Heightfield heights = flat_land(513, 2.0, 100.0f);
  PlacementRules rules;
  rules.tree_density = 0.4;
  rules.ground_density = 0.3;
  rules.species = {{"oak"}, {"short_grass"}};
  const double area = 1024.0 * 1024.0;
  // Evenly spread (clumping 0): the count is binomial, about 1 % off at most here.
  VegetationParams even = spaced(8.0, 2.0);
  even.clumping = 0.0;
  const Placement placement = place_plants(heights, even, rules);
  EXPECT_NEAR(double(placement.trees.size()), 0.4 * area / 64.0, 0.03 * 0.4 * area / 64.0);
  EXPECT_NEAR(double(placement.ground.size()), 0.3 * area / 4.0, 0.1 * 0.3 * area / 4.0);
  // Clumped (the default): the density field's mean is 1 over large areas, but a square
  // kilometre holds only a few groves and clearings: over eight seeds, within 15 %.
  double clumped_trees = 0.0;
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    VegetationParams clumped = spaced(8.0, 2.0);
    clumped.seed = seed;
    clumped.ground_density = 0.0;
    clumped_trees += static_cast<double>(place_plants(heights, clumped, rules).trees.size()) / 8.0;
  }
  EXPECT_NEAR(clumped_trees, 0.4 * area / 64.0, 0.15 * 0.4 * area / 64.0);

  // The [vegetation] section's density overrides the climate's.
  VegetationParams override = even;
  override.density = 0.1;
  override.ground_density = 0.0;
  const Placement sparse = place_plants(heights, override, rules);
  EXPECT_NEAR(double(sparse.trees.size()), 0.1 * area / 64.0, 0.1 * 0.1 * area / 64.0);
  EXPECT_TRUE(sparse.ground.empty());
}

TEST(Placement, AnOriginOffTheSampleGridStillWorks) {
  // Not a tile of a world whose samples sit at whole cells: still every plant inside, and the density.
  Heightfield heights = flat_land(257, 2.0, 50.0f);
  heights.origin_x_m = 0.7;
  heights.origin_y_m = -1000.3;
  PlacementRules rules;
  rules.species = {{"oak"}};
  VegetationParams even = spaced(4.0, 2.0);
  even.clumping = 0.0;
  const Placement placement = place_plants(heights, even, rules);
  EXPECT_NEAR(double(placement.trees.size()), 0.4 * 512.0 * 512.0 / 16.0, 0.05 * 0.4 * 512.0 * 512.0 / 16.0);
  for (const Instance& tree : placement.trees) {
    ASSERT_GE(tree.x_m, 0.7f);
    ASSERT_LE(tree.x_m, 512.7f);
    ASSERT_GE(tree.y_m, -1000.3f);
    ASSERT_LE(tree.y_m, -488.3f);
    ASSERT_EQ(tree.height_m, 50.0f);
  }
}

TEST(Placement, SpeciesFollowTheirBandsWithSoftEdges) {
  // A gentle ramp from 10 m to 390 m, tree line 400 m: oak low, spruce high.
  Heightfield heights(257, 257, 0.0f, 4.0);
  for (int y = 0; y < 257; ++y)
    for (int x = 0; x < 257; ++x) heights(x, y) = static_cast<float>(10.0 + 380.0 * x / 256.0);
  PlacementRules rules;
  rules.tree_density = 1.0;
  rules.tree_line_m = 400.0;
  rules.species = {{"oak", 0.0, 0.5}, {"spruce", 0.5, 1.0}};
  const Placement placement = place_plants(heights, spaced(8.0, 2.0), rules);
  const auto oak = species_index_for_test("oak");
  int oaks = 0, spruces = 0;
  for (const Instance& tree : placement.trees) {
    const double t = tree.height_m / 400.0;
    if (tree.species == oak) {
      ++oaks;
      EXPECT_LT(t, 0.5 + 0.1);
    } else {
      ++spruces;
      EXPECT_GT(t, 0.5 - 0.1);
    }
    if (t < 0.4) {
      EXPECT_EQ(tree.species, oak);
    }
    if (t > 0.6) {
      EXPECT_NE(tree.species, oak);
    }
  }
  EXPECT_GT(oaks, 1000);
  EXPECT_GT(spruces, 1000);
}

TEST(Placement, NearWaterSpeciesGrowOnlyByTheWater) {
  Heightfield heights(257, 257, 0.0f, 4.0);
  for (int y = 0; y < 257; ++y)
    for (int x = 0; x < 257; ++x) heights(x, y) = static_cast<float>(-20.0 + 200.0 * x / 256.0);  // 11 degrees
  PlacementRules rules = mixed_rules();
  rules.water_edge_m = 25.0;
  const Placement placement = place_plants(heights, spaced(6.0, 2.0), rules);
  const auto palm = species_index_for_test("date_palm");
  int palms = 0;
  for (const Instance& tree : placement.trees)
    if (tree.species == palm) {
      ++palms;
      EXPECT_LT(tree.height_m, rules.sea_level_m + rules.water_edge_m);
    }
  EXPECT_GT(palms, 50);
}

TEST(Placement, SummerOnlySpeciesAreAbsentInWinter) {
  const Heightfield heights = flat_land(129, 2.0, 90.0f);  // t = 0.75: moss's band
  PlacementRules rules = mixed_rules();
  const auto moss = species_index_for_test("moss");
  auto count_moss = [&](Season season) {
    rules.season = season;
    const Placement placement = place_plants(heights, spaced(8.0, 2.0), rules);
    return std::ranges::count_if(placement.ground, [&](const Instance& p) { return p.species == moss; });
  };
  EXPECT_GT(count_moss(Season::summer), 100);
  EXPECT_EQ(count_moss(Season::winter), 0);
  EXPECT_EQ(count_moss(Season::autumn), 0);
}

TEST(Placement, NoSpeciesNoPlants) {
  PlacementRules rules = mixed_rules();
  rules.species.clear();
  const Placement placement = place_plants(rough_terrain(), spaced(7.0, 1.3), rules);
  EXPECT_TRUE(placement.trees.empty());
  EXPECT_TRUE(placement.ground.empty());
}

TEST(Placement, DisabledOrNoForestBandPlacesNothing) {
  VegetationParams off = spaced(7.0, 1.3);
  off.enabled = false;
  EXPECT_TRUE(place_plants(rough_terrain(), off, mixed_rules()).trees.empty());
  PlacementRules upside_down = mixed_rules();
  upside_down.tree_line_m = upside_down.sea_level_m;
  const Placement none = place_plants(rough_terrain(), spaced(7.0, 1.3), upside_down);
  EXPECT_TRUE(none.trees.empty() && none.ground.empty());
}

TEST(Placement, BadParametersNameTheirKey) {
  VegetationParams params;
  params.density = -0.1;
  EXPECT_THAT(test::message_of([&] { params.validate(); }), HasSubstr("vegetation.density"));
  EXPECT_THAT(test::message_of([&] { (void)place_plants(flat_land(9, 1.0, 5.0f), params, mixed_rules()); }),
              HasSubstr("vegetation.density"));
  params = VegetationParams{};
  params.spacing_m = 0.0;
  EXPECT_THAT(test::message_of([&] { params.validate(); }), HasSubstr("vegetation.spacing"));
  params = VegetationParams{};
  params.ground_density = 1.5;
  EXPECT_THAT(test::message_of([&] { params.validate(); }), HasSubstr("vegetation.ground_density"));
  EXPECT_EQ(test::message_of([] { VegetationParams{}.validate(); }), "(no error)");
}

TEST(Placement, ParameterTableCoversEveryMember) {
  const auto& table = params::table_of<VegetationParams>();
  EXPECT_EQ(table.section, "vegetation");
  EXPECT_EQ(params::covered_fields(table), params::field_count<VegetationParams>());
  for (const auto& row : table.rows) EXPECT_FALSE(row.help.empty()) << row.key;
}

TEST(Placement, BadRulesAreInputErrors) {
  PlacementRules rules = mixed_rules();
  rules.species.push_back({"no_such_tree"});
  EXPECT_THAT(test::message_of([&] { (void)place_plants(flat_land(9, 1.0, 5.0f), VegetationParams{}, rules); }), HasSubstr("no_such_tree"));
  rules = mixed_rules();
  rules.species[0].band_low = 0.7;
  rules.species[0].band_high = 0.2;
  EXPECT_THAT(test::message_of([&] { (void)place_plants(flat_land(9, 1.0, 5.0f), VegetationParams{}, rules); }),
              HasSubstr("band 0.7..0.2"));
  rules = mixed_rules();
  rules.tree_density = -1.0;
  EXPECT_THAT(test::message_of([&] { (void)place_plants(flat_land(9, 1.0, 5.0f), VegetationParams{}, rules); }),
              HasSubstr("tree density -1"));
}

TEST(Placement, ReportsProgressInOrderAndStopsWhenCancelled) {
  std::vector<double> fractions;
  Context context;
  context.on_progress = [&](std::string_view stage, double fraction) {
    EXPECT_EQ(stage, "vegetation");
    fractions.push_back(fraction);
  };
  tbb::task_arena(2).execute([&] { (void)place_plants(rough_terrain(), spaced(7.0, 1.3), mixed_rules(), context); });
  ASSERT_FALSE(fractions.empty());
  EXPECT_LE(fractions.size(), 40u);
  EXPECT_TRUE(std::ranges::is_sorted(fractions));
  EXPECT_EQ(fractions.back(), 1.0);

  std::atomic<bool> cancel{true};
  context.cancel = &cancel;
  EXPECT_THROW((void)place_plants(rough_terrain(), spaced(7.0, 1.3), mixed_rules(), context), Cancelled);
}

}  // namespace
}  // namespace sansui::vegetation

namespace sansui::vegetation {
namespace {

/// Clark and Evans' (1954) aggregation index of the points inside `window` (x0, y0, x1, y1):
/// their mean nearest-neighbour distance over 0.5 / sqrt(density), the expectation for a
/// Poisson process of that density. Neighbours are searched among all points, so points near
/// the window's edge are not cut off from theirs (the border method of edge correction); the
/// window keeps a margin from the points' extent. R < 1: clustered, R = 1: random, R > 1: even.
/// `inside` picks the points (and their area: the window's share where inside(x, y) holds).
template <typename Inside>
double clark_evans(const std::vector<Instance>& points, double x0, double y0, double x1, double y1, Inside inside) {
  // Buckets of 16 m for the neighbour search.
  constexpr double bucket = 16.0;
  std::map<std::pair<int, int>, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < points.size(); ++i)
    grid[{static_cast<int>(std::floor(points[i].x_m / bucket)), static_cast<int>(std::floor(points[i].y_m / bucket))}].push_back(i);
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Instance& p = points[i];
    if (!(p.x_m >= x0 && p.x_m < x1 && p.y_m >= y0 && p.y_m < y1) || !inside(p.x_m, p.y_m)) continue;
    double nearest = 1e30;
    const int bx = static_cast<int>(std::floor(p.x_m / bucket)), by = static_cast<int>(std::floor(p.y_m / bucket));
    for (int ring = 1; ring <= 4 && nearest > (ring - 1) * bucket; ++ring)
      for (int dy = -ring; dy <= ring; ++dy)
        for (int dx = -ring; dx <= ring; ++dx) {
          const auto found = grid.find({bx + dx, by + dy});
          if (found == grid.end()) continue;
          for (std::size_t j : found->second)
            if (j != i) nearest = std::min(nearest, std::hypot(double{points[j].x_m} - p.x_m, double{points[j].y_m} - p.y_m));
        }
    sum += nearest;
    ++count;
  }
  // The area where inside() holds, on a 2 m lattice.
  double area = 0.0;
  for (double y = y0 + 1.0; y < y1; y += 2.0)
    for (double x = x0 + 1.0; x < x1; x += 2.0) area += inside(x, y) ? 4.0 : 0.0;
  EXPECT_GT(count, 200);
  const double density = count / area;
  return (sum / count) / (0.5 / std::sqrt(density));
}

PlacementRules oak_rules(double density) {
  PlacementRules rules;
  rules.tree_density = density;
  rules.tree_line_m = 1000.0;
  rules.species = {{"oak"}};
  return rules;
}

TEST(PlacementForest, TreesClusterWhereTheFieldSaysGrovesAndSpreadEvenlyWithoutIt) {
  // 2 km of flat land; the interior window keeps 100 m from the edge.
  const Heightfield heights = flat_land(1025, 2.0, 100.0f);
  const VegetationParams clumped = spaced(8.0, 2.0);
  const Placement forest = place_plants(heights, clumped, oak_rules(0.4));
  auto everywhere = [](double, double) { return true; };
  const double r_all = clark_evans(forest.trees, 100, 100, 1948, 1948, everywhere);
  EXPECT_LT(r_all, 0.9);
  // Inside groves (where the field is above its mean) the trees still cluster, in clumps.
  auto in_groves = [&](double x, double y) { return density_field(clumped.seed, x, y) > 1.2; };
  const double r_groves = clark_evans(forest.trees, 100, 100, 1948, 1948, in_groves);
  EXPECT_LT(r_groves, 1.0);
  // Evenly spread: the jittered grid is more regular than random.
  VegetationParams even = clumped;
  even.clumping = 0.0;
  const double r_even = clark_evans(place_plants(heights, even, oak_rules(0.4)).trees, 100, 100, 1948, 1948, everywhere);
  EXPECT_GT(r_even, 1.0);
  EXPECT_LT(r_all, r_even - 0.2);
  RecordProperty("clark_evans_clumped", std::to_string(r_all));
  RecordProperty("clark_evans_groves", std::to_string(r_groves));
  RecordProperty("clark_evans_even", std::to_string(r_even));
  // And there are clearings: a tenth of the land or more has no tree within 12 m.
  int open = 0, probes = 0;
  for (double y = 110; y < 1940; y += 20)
    for (double x = 110; x < 1940; x += 20) {
      ++probes;
      bool near = false;
      for (const Instance& t : forest.trees)
        if (std::abs(t.x_m - x) < 12 && std::abs(t.y_m - y) < 12 && std::hypot(t.x_m - x, t.y_m - y) < 12) {
          near = true;
          break;
        }
      open += near ? 0 : 1;
    }
  EXPECT_GT(open, probes / 10);
}

TEST(PlacementForest, DensityFieldHasMeanOne) {
  // Over 64 km^2 and several seeds: the climate's density is the mean density.
  for (std::uint64_t seed : {1u, 2u, 77u, 1234u}) {
    double sum = 0.0;
    int count = 0;
    for (double y = 4.0; y < 8000.0; y += 8.0)
      for (double x = 4.0; x < 8000.0; x += 8.0, ++count) sum += density_field(seed, x, y);
    EXPECT_NEAR(sum / count, 1.0, 0.08) << "seed " << seed;
  }
}

TEST(PlacementForest, TreeHeightsSpreadWithManyYoungAndFewOld) {
  const Placement forest = place_plants(flat_land(513, 2.0, 100.0f), spaced(8.0, 2.0), oak_rules(0.4));
  ASSERT_GT(forest.trees.size(), 1000u);
  double sum = 0.0, squares = 0.0;
  int small = 0, large = 0;
  for (const Instance& t : forest.trees) {
    sum += t.scale, squares += double{t.scale} * t.scale;
    small += t.scale < 0.85 ? 1 : 0;
    large += t.scale > 1.25 ? 1 : 0;
  }
  const double n = static_cast<double>(forest.trees.size()), mean = sum / n;
  const double deviation = std::sqrt(std::max(squares / n - mean * mean, 0.0));
  EXPECT_GT(deviation / mean, 0.2);  // coefficient of variation
  RecordProperty("height_cv", std::to_string(deviation / mean));
  EXPECT_GT(small, 2 * large);  // many young, few old
  EXPECT_GT(large, 0);
}

TEST(PlacementForest, NeighboursAreOftenOfOneSpecies) {
  // Oak and beech mixed half and half over the whole band: a tree's nearest neighbour is of its
  // own species more often than a random pair is (patches, not salt and pepper).
  PlacementRules rules = oak_rules(0.4);
  rules.species = {{"oak"}, {"beech"}};
  const Placement forest = place_plants(flat_land(513, 2.0, 100.0f), spaced(8.0, 2.0), rules);
  const auto oak = species_index_for_test("oak");
  std::map<std::pair<int, int>, std::vector<std::size_t>> grid;
  for (std::size_t i = 0; i < forest.trees.size(); ++i)
    grid[{static_cast<int>(forest.trees[i].x_m / 16), static_cast<int>(forest.trees[i].y_m / 16)}].push_back(i);
  int same = 0, pairs = 0, oaks = 0;
  for (std::size_t i = 0; i < forest.trees.size(); ++i) {
    const Instance& t = forest.trees[i];
    oaks += t.species == oak ? 1 : 0;
    double nearest = 1e30;
    std::size_t found = i;
    const int bx = static_cast<int>(t.x_m / 16), by = static_cast<int>(t.y_m / 16);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const auto cell = grid.find({bx + dx, by + dy});
        if (cell == grid.end()) continue;
        for (std::size_t j : cell->second) {
          const double d = std::hypot(forest.trees[j].x_m - t.x_m, forest.trees[j].y_m - t.y_m);
          if (j != i && d < nearest) nearest = d, found = j;
        }
      }
    if (found == i) continue;
    ++pairs;
    same += forest.trees[found].species == t.species ? 1 : 0;
  }
  const double p = static_cast<double>(oaks) / static_cast<double>(forest.trees.size());
  const double random_same = p * p + (1 - p) * (1 - p);
  EXPECT_GT(p, 0.2);
  EXPECT_LT(p, 0.8);
  EXPECT_GT(static_cast<double>(same) / pairs, random_same + 0.1);
  RecordProperty("same_species_neighbours", std::to_string(static_cast<double>(same) / pairs));
  RecordProperty("same_species_random", std::to_string(random_same));
}

TEST(PlacementForest, HumidWarmTemperateLowlandsAreMixedStands) {
  // A hill a tenth of the way to the tree line (forest-walk's land in Cfa): oaks, maples, red
  // pines and sugi all grow there, and none takes more than half of the trees (issue 49: the
  // scene was 97 % oak, its conifers only above half the tree line).
  for (const char* koppen : {"Cfa", "Cw"}) {
    PlacementRules rules = oak_rules(0.5);
    rules.species = species_of_climate(koppen);
    const Placement forest = place_plants(flat_land(257, 4.0, 100.0f), spaced(8.0, 2.0), rules);
    std::map<std::uint16_t, int> count;
    for (const Instance& tree : forest.trees) ++count[tree.species];
    ASSERT_GT(forest.trees.size(), 1000u) << koppen;
    EXPECT_EQ(count.size(), 4u) << koppen;
    for (const auto& [species, n] : count) {
      const double share = static_cast<double>(n) / static_cast<double>(forest.trees.size());
      EXPECT_GT(share, 0.08) << koppen << " " << species_library()[species].name;
      EXPECT_LT(share, 0.5) << koppen << " " << species_library()[species].name;
    }
  }
}

}  // namespace
}  // namespace sansui::vegetation

// A scene's plants (scene/plants.hpp): the climate decides which grow and how densely (Table 1
// and Table 4), none above the tree line or under the sea, deserts and ice without trees, and
// `sansui tree` draws or exports one plant and refuses what it does not know.
#include "scene/plants.hpp"

#include <cmath>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/mesh_io.hpp"
#include "scene/look.hpp"
#include "terrain/midpoint.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/test_paths.hpp"
#include "tests/test_util.hpp"

namespace sansui::scene {
namespace {

using ::testing::HasSubstr;

/// A fractal island: sea around, land up to a peak.
Heightfield island() {
  Heightfield heights = terrain::generate_midpoint({5, 0.8, 300.0, true}, 257);
  heights.cell_size_m = 20.0;
  return heights;
}

vegetation::Placement plants_of(Climate climate, Season season, const Heightfield& heights) {
  Recipe recipe;
  recipe.climate.koppen = climate;
  recipe.season.season = season;
  resolve_look(recipe);
  return place_scene_plants(recipe, heights, quiet_context());
}

const vegetation::Species& species_of(const vegetation::Instance& plant) {
  return vegetation::species_library()[plant.species];
}

TEST(ScenePlants, TheDesertHasOnlyCactiAndPalmsByTheWaterAndTheIceCapNothing) {
  const Heightfield heights = island();
  Recipe recipe;
  recipe.climate.koppen = Climate::BW;
  resolve_look(recipe);
  const vegetation::PlacementRules rules = placement_rules(recipe, heights);
  const vegetation::Placement desert = plants_of(Climate::BW, Season::summer, heights);
  ASSERT_FALSE(desert.trees.empty());
  for (const vegetation::Instance& plant : desert.trees) {
    const vegetation::Species& species = species_of(plant);
    if (species.form != vegetation::Form::succulent) {
      EXPECT_EQ(species.name, "date_palm");
      EXPECT_LT(plant.height_m, rules.sea_level_m + rules.water_edge_m) << "a date palm away from water";
    }
  }
  const vegetation::Placement ice = plants_of(Climate::EF, Season::summer, heights);
  EXPECT_TRUE(ice.trees.empty());
  EXPECT_TRUE(ice.ground.empty());
  // Tundra: no trees; moss in summer only.
  EXPECT_TRUE(plants_of(Climate::ET, Season::summer, heights).trees.empty());
  EXPECT_FALSE(plants_of(Climate::ET, Season::summer, heights).ground.empty());
  EXPECT_TRUE(plants_of(Climate::ET, Season::winter, heights).ground.empty());
}

TEST(ScenePlants, NoPlantStandsAboveTheTreeLineOrInTheSea) {
  const Heightfield heights = island();
  for (Climate climate : {Climate::Af, Climate::Cfb, Climate::Df}) {
    Recipe recipe;
    recipe.climate.koppen = climate;
    resolve_look(recipe);
    const vegetation::PlacementRules rules = placement_rules(recipe, heights);
    const vegetation::Placement plants = place_scene_plants(recipe, heights, quiet_context());
    ASSERT_FALSE(plants.trees.empty());
    for (const auto* layer : {&plants.trees, &plants.ground})
      for (const vegetation::Instance& plant : *layer) {
        ASSERT_GT(plant.height_m, rules.sea_level_m);
        ASSERT_LE(plant.height_m, rules.tree_line_m);
      }
  }
}

TEST(ScenePlants, OnFlatLandTheTreeCountMatchesTheClimatesDensity) {
  // Flat land 1 m above the sea (inside the forest band) of 4 km x 4 km; Cfb: Table 4's 40 %.
  Heightfield heights(401, 401, 1.0f, 10.0);
  heights(0, 0) = 100.0f;  // a peak in a corner, so the flat land is low in the forest band
  Recipe recipe;
  recipe.climate.koppen = Climate::Cfb;
  resolve_look(recipe);
  const vegetation::Placement plants = place_scene_plants(recipe, heights, quiet_context());
  const double area = 4000.0 * 4000.0;
  const double expected = *recipe.vegetation.density * area / (recipe.vegetation.spacing_m * recipe.vegetation.spacing_m);
  // Trees gather in groves and leave clearings (issue 31): 16 km^2 hold a few dozen of each,
  // so the count is the climate's within 20 %; evenly spread, within 10 %.
  EXPECT_NEAR(static_cast<double>(plants.trees.size()), expected, 0.2 * expected);
  recipe.vegetation.clumping = 0.0;
  const vegetation::Placement even = place_scene_plants(recipe, heights, quiet_context());
  EXPECT_NEAR(static_cast<double>(even.trees.size()), expected, 0.1 * expected);
}

TEST(ScenePlants, PicturesOfLargeTerrainsLeaveOutTheGroundLayer) {
  Recipe recipe;
  recipe.vegetation.spacing_m = 100.0;  // few trees: the test is about the ground layer
  resolve_look(recipe);
  Heightfield small(101, 101, 1.0f, 10.0);  // 1 km: 250,000 ground cells
  small(0, 0) = 100.0f;
  EXPECT_FALSE(plants_to_draw(recipe, small, quiet_context()).ground.empty());
  Heightfield large(101, 101, 1.0f, 50.0);  // 5 km: 6.25 M ground cells
  large(0, 0) = 100.0f;
  EXPECT_TRUE(plants_to_draw(recipe, large, quiet_context()).ground.empty());
  EXPECT_FALSE(plants_to_draw(recipe, large, quiet_context()).trees.empty());
  EXPECT_FALSE(place_scene_plants(recipe, large, quiet_context()).ground.empty()) << "plant lists keep every plant";
}

// Issue 49: a camera standing in a large terrain sees the ground plants around it, the same
// plants the whole terrain's ground layer has there; an overview still leaves them out.
TEST(ScenePlants, ACameraNearTheGroundOfALargeTerrainStandsInItsGroundPlants) {
  Recipe recipe;
  recipe.vegetation.spacing_m = 100.0;
  resolve_look(recipe);
  Heightfield large(101, 101, 1.0f, 50.0);  // 5 km: 6.25 M ground cells, over the whole-terrain limit
  large(0, 0) = 100.0f;
  recipe.render.camera.eye_height_m = 1.7;
  recipe.render.camera.target_x = 0.3, recipe.render.camera.target_y = 0.6;
  const vegetation::Placement picture = plants_for_picture(recipe, large, quiet_context());
  ASSERT_FALSE(picture.ground.empty());
  const double eye_x = 0.3 * 5000.0, eye_y = 0.6 * 5000.0;
  for (const auto& plant : picture.ground)
    EXPECT_LE(std::max(std::abs(plant.x_m - eye_x), std::abs(plant.y_m - eye_y)), ground_plants_reach_m + 50.0);
  // The very plants of the whole layer in that square (placement is keyed by world position).
  std::size_t inside = 0;
  const auto whole = place_scene_plants(recipe, large, quiet_context()).ground;
  const auto first = std::ranges::find_if(
      whole, [&](const auto& plant) { return plant.x_m == picture.ground.front().x_m && plant.y_m == picture.ground.front().y_m; });
  EXPECT_NE(first, whole.end());
  for (const auto& plant : whole)
    inside += std::abs(plant.x_m - picture.ground.front().x_m) < 1e-3 && std::abs(plant.y_m - picture.ground.front().y_m) < 1e-3 &&
              plant.species == picture.ground.front().species;
  EXPECT_EQ(inside, 1u);
  // High above the ground (or a fitted overview) the picture has no ground layer.
  recipe.render.camera.eye_height_m = 400.0;
  EXPECT_TRUE(plants_for_picture(recipe, large, quiet_context()).ground.empty());
  recipe.render.camera.eye_height_m.reset();
  EXPECT_TRUE(plants_for_picture(recipe, large, quiet_context()).ground.empty());
}

TEST(ScenePlants, DisabledVegetationPlacesNothing) {
  Recipe recipe;
  recipe.vegetation.enabled = false;
  resolve_look(recipe);
  EXPECT_TRUE(place_scene_plants(recipe, island(), quiet_context()).trees.empty());
}

TEST(TreeCli, DrawsAPictureAndExportsTheSameTreeAsAMesh) {
  test::TempDir dir("tree-cli");
  const auto run = test::run_cli_line(
      "tree --species saguaro --season spring --width 96 --height 96 --samples 1 -o cactus.png -o cactus.glb", dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const TriangleMesh mesh = io::read_mesh(dir / "cactus.glb");
  Recipe recipe;
  recipe.tree.species = "saguaro";
  recipe.season.season = Season::spring;
  EXPECT_EQ(mesh.triangle_count(), tree_mesh_of(recipe).triangle_count());
  EXPECT_TRUE(std::filesystem::exists(dir / "cactus.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "cactus.png.json"));
}

TEST(TreeCli, DrawsASpeciesOfTheUsersOwnFile) {
  test::TempDir dir("tree-own");
  const std::string willow = std::string(sansui::test::source_dir) + "/examples/species/weeping-willow.toml";
  const auto run = test::run_cli_line(
      "tree --species-file '" + willow + "' --species weeping_willow --width 64 --height 64 --samples 1 -o willow.png -o willow.glb",
      dir.path());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_GT(io::read_mesh(dir / "willow.glb").triangle_count(), 1000u);
  EXPECT_TRUE(std::filesystem::exists(dir / "willow.png"));
}

TEST(TreeCli, ABadSpeciesFileIsRefusedNamingTheLineAndKey) {
  test::TempDir dir("tree-own-bad");
  std::ofstream(dir / "deep.toml") << "[[species]]\nname = \"x\"\ndepth = 9\n";
  const auto deep = test::run_cli_line("tree --species-file deep.toml --species x -o x.png", dir.path());
  EXPECT_EQ(deep.exit_code, 2);
  EXPECT_THAT(deep.err, HasSubstr("deep.toml:3: [species] depth = 9 is not allowed: it must be between 0 and 8"));
  std::ofstream(dir / "typo.toml") << "[[species]]\nname = \"x\"\nbranch_angel = 30\n";
  const auto typo = test::run_cli_line("tree --species-file typo.toml --species x -o x.png", dir.path());
  EXPECT_EQ(typo.exit_code, 2);
  EXPECT_THAT(typo.err, HasSubstr("typo.toml:3: [species] branch_angel is not a key: allowed are name"));
  std::ofstream(dir / "climate.toml") << "[climate.Cfb]\ntrees = []\n";
  const auto climate = test::run_cli_line("tree --species-file climate.toml --species oak -o x.png", dir.path());
  EXPECT_EQ(climate.exit_code, 2);
  EXPECT_THAT(climate.err, HasSubstr("only [[species]] tables"));
  const auto missing = test::run_cli_line("tree --species-file own.toml --species maple_tree -o x.png", dir.path());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

TEST(TreeCli, AnUnknownSpeciesOrABadSeasonIsRefusedWithNoFile) {
  test::TempDir dir("tree-bad");
  const auto species = test::run_cli_line("tree --species unicorn -o x.png", dir.path());
  EXPECT_EQ(species.exit_code, 2);
  EXPECT_THAT(species.err, HasSubstr("unicorn"));
  EXPECT_THAT(species.err, HasSubstr("spruce"));
  const auto season = test::run_cli_line("tree --species oak --season monsoon -o x.png", dir.path());
  EXPECT_EQ(season.exit_code, 2);
  EXPECT_THAT(season.err, HasSubstr("monsoon"));
  const auto density = test::run_cli_line("render --plants-density -0.5 in.png -o x.png", dir.path());
  EXPECT_EQ(density.exit_code, 2);
  EXPECT_THAT(density.err, HasSubstr("density"));
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

}  // namespace
}  // namespace sansui::scene

// A scene's parts (scene/scenery.hpp): the same heights as recipe_heights(), every map on the
// heights' grid, splat weights that sum to 255, water that is the sea's depth below sea level,
// plants standing on the ground inside the terrain in the scene's frame (x east, y north).
#include "scene/scenery.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "look/surface_layers.hpp"
#include "scene/pipeline.hpp"

namespace sansui::scene {
namespace {

Recipe small_world() {
  Recipe recipe = default_recipe(SourceKind::midpoint);
  recipe.world.size = 129;
  recipe.world.cell_m = 20.0;
  recipe.midpoint.seed = 3;
  return recipe;
}

std::vector<std::string> names_of(const std::vector<const Section*>& sections) {
  std::vector<std::string> names(sections.size());
  std::transform(sections.begin(), sections.end(), names.begin(), [](const Section* section) { return section->name; });
  return names;
}

TEST(Scenery, ReadsTheSectionsOfTheLookNotThoseOfSources) {
  const std::vector<std::string> names = names_of(scenery_sections());
  for (const char* wanted : {"render", "climate", "season", "weather", "time", "land", "sea", "vegetation", "flow", "tree"})
    EXPECT_NE(std::find(names.begin(), names.end(), wanted), names.end()) << wanted;
  for (const char* unwanted : {"midpoint", "file", "contour", "solid", "map"})
    EXPECT_EQ(std::find(names.begin(), names.end(), unwanted), names.end()) << unwanted;
}

TEST(Scenery, SplatWeightsSumTo255AndRoundToTheNearest) {
  look::SurfaceWeights weights{Grid<float>(2, 1, 0.0f), Grid<float>(2, 1, 0.0f), Grid<float>(2, 1, 0.0f), Grid<float>(2, 1, 0.0f)};
  weights.sand(0, 0) = 1.0f;
  for (Grid<float>* layer : {&weights.sand, &weights.grass, &weights.rock, &weights.snow}) (*layer)(1, 0) = 0.25f;
  const Image image = look::splat_weights_image(weights);
  EXPECT_EQ(image(0, 0).r, 255);
  EXPECT_EQ(image(0, 0).g, 0);
  const Rgba8 even = image(1, 0);
  EXPECT_EQ(even.r + even.g + even.b + even.a, 255);
  EXPECT_GE(std::min({even.r, even.g, even.b, even.a}), 63);
}

TEST(Scenery, WaterIsTheSeasDepthBelowSeaLevelAndTheLakesElsewhere) {
  Heightfield heights(3, 1, 0.0f, 5.0);
  heights(0, 0) = -4.0f, heights(1, 0) = 2.0f, heights(2, 0) = 10.0f;
  Grid<float> lakes(3, 1, 0.0f);
  lakes(2, 0) = 1.5f;
  const Grid<float> depth = water_depth(heights, lakes, true, 0.0);
  EXPECT_EQ(depth(0, 0), 4.0f);
  EXPECT_EQ(depth(1, 0), 0.0f);
  EXPECT_EQ(depth(2, 0), 1.5f);
  EXPECT_EQ(depth.cell_size_m, 5.0);
  EXPECT_EQ(water_depth(heights, Grid<float>(), false, 0.0)(0, 0), 0.0f) << "no sea: dry";
}

TEST(Scenery, PlantsStandInTheScenesFrameEastAndNorthOfTheFirstSample) {
  Heightfield heights(3, 3, 0.0f, 10.0);
  heights.origin_x_m = 1000.0, heights.origin_y_m = 2000.0;
  vegetation::Placement placement;
  vegetation::Instance tree;
  tree.x_m = 1015.0f, tree.y_m = 2005.0f, tree.height_m = 7.0f, tree.species = 2, tree.variant = 3, tree.rotation_rad = 1.0f;
  placement.trees.push_back(tree);
  placement.ground.push_back(tree);
  const std::vector<SceneryPlant> plants = scenery_plants(placement, heights);
  ASSERT_EQ(plants.size(), 2u);
  EXPECT_EQ(plants[0].x_m, 15.0f);
  EXPECT_EQ(plants[0].y_m, -5.0f);
  EXPECT_EQ(plants[0].z_m, 7.0f);
  EXPECT_EQ(plants[0].species, 2);
  EXPECT_EQ(plants[0].variant, 3);
  EXPECT_EQ(plants[0].rotation_rad, 1.0f);
  EXPECT_EQ(plants[0].layer, 0);
  EXPECT_EQ(plants[1].layer, 1);
}

TEST(Scenery, MakesTheRecipesHeightsAndEveryMapOnTheirGrid) {
  const Recipe recipe = small_world();
  const Scenery scenery = make_scenery(recipe);
  const Heightfield heights = recipe_heights(recipe);
  ASSERT_EQ(scenery.heights.width(), heights.width());
  EXPECT_EQ(std::memcmp(scenery.heights.data(), heights.data(), heights.size() * sizeof(float)), 0);
  for (const auto* image : {&scenery.colour, &scenery.splat}) {
    EXPECT_EQ(image->width(), 129);
    EXPECT_EQ(image->height(), 129);
  }
  EXPECT_EQ(scenery.water_m.width(), 129);
  for (const Rgba8& p : scenery.splat.values()) ASSERT_EQ(p.r + p.g + p.b + p.a, 255);
  for (std::size_t i = 0; i < heights.size(); ++i) {
    const double below = scenery.sea_level_m - heights.values()[i];
    ASSERT_GE(scenery.water_m.values()[i], std::max(0.0, below) - 1e-3);
  }
  ASSERT_FALSE(scenery.plants.empty());
  const double extent = 128 * 20.0;
  for (const SceneryPlant& plant : scenery.plants) {
    ASSERT_GE(plant.x_m, 0.0f);
    ASSERT_LE(plant.x_m, extent);
    ASSERT_LE(plant.y_m, 0.0f);
    ASSERT_GE(plant.y_m, -extent);
    ASSERT_LT(plant.species, scenery.species.size());
    ASSERT_GT(plant.z_m, scenery.sea_level_m) << "no plant under the sea";
    // The ground under it: between the heights of the four samples around it.
    const int column = std::min(static_cast<int>(plant.x_m / 20.0), 127), row = std::min(static_cast<int>(-plant.y_m / 20.0), 127);
    const float low = std::min({heights(column, row), heights(column + 1, row), heights(column, row + 1), heights(column + 1, row + 1)});
    const float high = std::max({heights(column, row), heights(column + 1, row), heights(column, row + 1), heights(column + 1, row + 1)});
    ASSERT_GE(plant.z_m, low - 1e-3f);
    ASSERT_LE(plant.z_m, high + 1e-3f);
  }
}

}  // namespace
}  // namespace sansui::scene

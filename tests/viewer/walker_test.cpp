#include "viewer/walker.hpp"

#include <algorithm>
#include <chrono>
#include <string>
#include <thread>
#include <tuple>

#include <gtest/gtest.h>

#include "scene/recipe.hpp"
#include "viewer/scene_builder.hpp"

namespace sansui::viewer {
namespace {

TEST(Walker, WalksAlongItsBearingAndStaysOnTheTerrain) {
  Walker walker;
  walker.x_m = 500.0;
  walker.z_m = 500.0;
  walker.bearing_deg = 90.0;  // east
  walk(walker, 100.0, 0.0, 1000.0, 1000.0);
  EXPECT_NEAR(walker.x_m, 600.0, 1e-9);
  EXPECT_NEAR(walker.z_m, 500.0, 1e-9);
  walk(walker, 0.0, 50.0, 1000.0, 1000.0);  // to the right of east is south (+z)
  EXPECT_NEAR(walker.z_m, 550.0, 1e-9);
  walker.bearing_deg = 0.0;  // north is -z
  walk(walker, 10'000.0, 0.0, 1000.0, 1000.0);
  EXPECT_EQ(walker.z_m, 0.0);  // kept on the terrain
  look(walker, -30.0, 200.0);
  EXPECT_NEAR(walker.bearing_deg, 330.0, 1e-9);
  EXPECT_EQ(walker.pitch_deg, 85.0);
  const look::Camera camera = walker_camera(walker, 1000.0, 2000.0, 50.0, 3.0);
  EXPECT_NEAR(camera.target_x, 0.6, 1e-9);
  EXPECT_NEAR(*camera.eye_height_m, 4.7, 1e-9);
  EXPECT_EQ(camera.azimuth_deg, 330.0);
}

// What a change makes stale follows from the keys of what each thing is made from.
Stale stale_after(std::string_view key, const params::Value& value) {
  scene::Recipe recipe = scene::default_recipe(scene::SourceKind::midpoint);
  recipe.shape.push_back(scene::default_erode_step());
  recipe.base_dir = "/tmp";
  scene::Recipe changed = recipe;
  scene::recipe_table().find(key)->set(changed, value);
  return stale_between(build_keys(recipe), build_keys(changed));
}

TEST(SceneBuilder, AChangeMakesStaleOnlyWhatDependsOnIt) {
  const Stale hurst = stale_after("midpoint.hurst", 0.5);
  EXPECT_TRUE(hurst.heights && hurst.rock && hurst.plants && hurst.water);
  EXPECT_FALSE(hurst.sky);  // the sky does not depend on the ground
  // Winter changes the plants; the sky follows the date, not the season.
  const Stale season = stale_after("season.season", std::string("winter"));
  EXPECT_FALSE(season.heights || season.water || season.sky);
  EXPECT_TRUE(season.plants);
  const Stale weather = stale_after("weather.weather", std::string("cloudy"));
  EXPECT_TRUE(weather.sky && weather.plants);
  EXPECT_FALSE(weather.heights || weather.water);
  const Stale time = stale_after("time.time", std::string("09:00"));
  EXPECT_TRUE(time.sky);
  EXPECT_FALSE(time.heights || time.plants || time.rock || time.water);
  EXPECT_FALSE(stale_after("land.snow", std::vector<double>{0.9, 0.9, 0.9}).any());  // a colour: drawn next frame
  EXPECT_FALSE(stale_after("render.exaggeration", 2.0).any());
  EXPECT_FALSE(stale_after("camera.azimuth", 10.0).any());
  EXPECT_TRUE(stale_after("land.tree_line_m", 300.0).plants);
  EXPECT_TRUE(stale_after("rock.texture", std::string("strata")).rock);
  const Stale flow = stale_after("flow.channel_area", 5e5);
  EXPECT_TRUE(flow.water && flow.plants);  // plants are kept out of the rivers
  EXPECT_FALSE(flow.heights || flow.rock || flow.sky);
  // The sea level moves the water's edge and where trees stand (a hand-written table missed this).
  const Stale sea = stale_after("render.sea_level", 20.0);
  EXPECT_TRUE(sea.water && sea.plants);
  EXPECT_FALSE(sea.heights);
}

TEST(SceneBuilder, GoingBackToAnEarlierTerrainTakesItFromMemory) {
  scene::Recipe recipe = scene::default_recipe(scene::SourceKind::midpoint);
  recipe.world.size = 129;
  recipe.shape.push_back(scene::default_erode_step());
  recipe.base_dir = "/tmp";
  SceneBuilder builder;
  auto finish = [&](const scene::Recipe& r) {
    const Stale stale = builder.request(r);
    std::optional<SceneBuild> build;
    while (!(build = builder.take())) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_EQ(build->error, "");
    return std::make_pair(stale, *build);
  };
  const auto [first_stale, first] = finish(recipe);
  EXPECT_TRUE(first_stale.heights && first_stale.sky);
  scene::Recipe rougher = recipe;
  rougher.midpoint.hurst = 0.5;
  const auto [second_stale, second] = finish(rougher);
  EXPECT_TRUE(second_stale.heights);
  EXPECT_FALSE(second_stale.sky);
  EXPECT_FALSE(second.sky);
  EXPECT_FALSE(std::ranges::equal(first.heights->values(), second.heights->values()));
  const auto [back_stale, back] = finish(recipe);
  EXPECT_TRUE(back_stale.heights);
  EXPECT_EQ(back.heights.get(), first.heights.get());  // the same grid: not made again
  // Its rock, water and plants too: the evaluator keeps the scene's parts with its terrains.
  ASSERT_TRUE(first.rock && first.water && first.plants);
  EXPECT_EQ(std::tuple(back.rock.get(), back.water.get(), back.plants.get()),
            std::tuple(first.rock.get(), first.water.get(), first.plants.get()));
  EXPECT_FALSE(builder.request(recipe).any());  // nothing to do
  EXPECT_FALSE(builder.busy());
  // A scene opened anew reads its files again: nothing is kept.
  builder.forget();
  const auto [again_stale, again] = finish(recipe);
  EXPECT_TRUE(again_stale.heights && again_stale.sky);
  EXPECT_NE(again.heights.get(), first.heights.get());
  EXPECT_TRUE(std::ranges::equal(again.heights->values(), first.heights->values()));
}

}  // namespace
}  // namespace sansui::viewer

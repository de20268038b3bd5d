#include "viewer/walker.hpp"

#include <gtest/gtest.h>

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

TEST(SceneBuilder, AChangeMakesStaleOnlyWhatDependsOnIt) {
  const Stale hurst = stale_after_change("midpoint.hurst");
  EXPECT_TRUE(hurst.heights && hurst.rock && hurst.plants);
  EXPECT_FALSE(hurst.sky);  // the sky does not depend on the ground
  const Stale season = stale_after_change("season.season");
  EXPECT_FALSE(season.heights);
  EXPECT_TRUE(season.plants && season.sky);
  const Stale time = stale_after_change("time.time");
  EXPECT_TRUE(time.sky);
  EXPECT_FALSE(time.heights || time.plants || time.rock);
  EXPECT_FALSE(stale_after_change("land.snow").any());  // a colour: drawn next frame
  EXPECT_FALSE(stale_after_change("render.exaggeration").any());
  EXPECT_TRUE(stale_after_change("land.tree_line").plants);
  EXPECT_TRUE(stale_after_change("rock.texture").rock);
}

}  // namespace
}  // namespace sansui::viewer

#include "look/camera.hpp"

#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/error.hpp"

namespace sansui::look {
namespace {

glm::dvec2 project(const CameraMatrices& camera, glm::dvec3 point) {
  const glm::dvec4 clip = glm::dmat4(camera.projection) * glm::dmat4(camera.view) * glm::dvec4(point, 1.0);
  return {clip.x / clip.w, clip.y / clip.w};
}

TEST(Camera, TopViewShowsTheWholeTerrainNorthUp) {
  RenderParams params;
  params.view = View::top;
  const TerrainFrame frame{2000.0, 1000.0, -50.0, 400.0, 0.0, {}};
  const CameraMatrices camera = camera_matrices(params, frame, 400, 200);  // same aspect: fills it
  EXPECT_TRUE(camera.orthographic);
  const glm::dvec2 north_west = project(camera, {0.0, 100.0, 0.0});
  const glm::dvec2 south_east = project(camera, {2000.0, 100.0, 1000.0});
  EXPECT_NEAR(north_west.x, -1.0, 1e-5);
  EXPECT_NEAR(north_west.y, 1.0, 1e-5);  // north at the top
  EXPECT_NEAR(south_east.x, 1.0, 1e-5);
  EXPECT_NEAR(south_east.y, -1.0, 1e-5);
  // A square picture letterboxes the 2:1 terrain: it fills the width only.
  const CameraMatrices square = camera_matrices(params, frame, 300, 300);
  EXPECT_NEAR(project(square, {0.0, 0.0, 0.0}).y, 0.5, 1e-5);
  EXPECT_NEAR(project(square, {2000.0, 0.0, 0.0}).x, 1.0, 1e-5);
}

TEST(Camera, FittedPerspectiveKeepsEveryPointInTheFrameWithSkyAboveOrCentredLookingDown) {
  std::vector<glm::dvec3> points;
  for (double x : {0.0, 500.0, 1000.0})
    for (double z : {0.0, 500.0, 1000.0}) points.push_back({x, x == 500.0 && z == 500.0 ? 300.0 : 20.0, z});
  for (double x : {0.0, 1000.0})
    for (double z : {0.0, 1000.0}) points.push_back({x, -40.0, z});
  const TerrainFrame frame{1000.0, 1000.0, -40.0, 300.0, 50.0, points};
  for (double azimuth : {0.0, 135.0, 200.0, 290.0})
    for (double elevation : {10.0, 25.0, 60.0, 89.0}) {
      RenderParams params;
      params.camera.azimuth_deg = azimuth;
      params.camera.elevation_deg = elevation;
      const CameraMatrices camera = camera_matrices(params, frame, 1280, 720);
      double top = -1.0, bottom = 1.0, left = 1.0, right = -1.0;
      for (const glm::dvec3& point : points) {
        const glm::dvec2 p = project(camera, point);
        top = std::max(top, p.y), bottom = std::min(bottom, p.y);
        left = std::min(left, p.x), right = std::max(right, p.x);
      }
      const std::string at = fmt::format("azimuth {} elevation {}", azimuth, elevation);
      EXPECT_NEAR(left, -right, 1e-3) << at;  // centred across
      EXPECT_LE(right, 0.9401) << at;
      if (elevation <= 30.0) {
        EXPECT_NEAR(bottom, -0.94, 1e-3) << at;  // sits on the bottom margin
        EXPECT_LE(top, 0.56) << at;              // sky above
        // Tight: it fills the width or the band under the sky.
        EXPECT_TRUE(right > 0.93 || top > 0.54) << at << ": " << right << " " << top;
      } else {
        // Looking down no sky shows above it: centred, the same margin all round, and tight.
        EXPECT_NEAR(bottom, -top, 1e-3) << at;
        EXPECT_LE(top, 0.9401) << at;
        EXPECT_TRUE(right > 0.93 || top > 0.93) << at << ": " << right << " " << top;
      }
    }
}

TEST(Camera, AzimuthIsTheCompassBearingFromTheTargetToTheCamera) {
  const TerrainFrame frame{1000.0, 1000.0, 0.0, 100.0, 0.0, {}};
  RenderParams params;
  params.camera.distance = 2.0;
  params.camera.elevation_deg = 30.0;
  params.camera.azimuth_deg = 180.0;  // south of the target: z larger
  EXPECT_GT(camera_matrices(params, frame, 100, 100).position.z, 1500.0f);
  params.camera.azimuth_deg = 90.0;  // east: x larger
  const CameraMatrices east = camera_matrices(params, frame, 100, 100);
  EXPECT_GT(east.position.x, 1500.0f);
  EXPECT_NEAR(east.position.y, 1000.0, 1.0);  // 2000 m * sin 30
  // The target projects to the centre of the picture.
  const glm::dvec2 centre = project(east, {500.0, 0.0, 500.0});
  EXPECT_NEAR(centre.x, 0.0, 1e-5);
  EXPECT_NEAR(centre.y, 0.0, 1e-5);
}

TEST(Camera, FrontAndSideViewsAreLevelElevationsOfTheWholeBlock) {
  const TerrainFrame frame{2000.0, 1000.0, -50.0, 400.0, 0.0, {}};
  RenderParams params;
  params.view = View::front;
  const CameraMatrices front = camera_matrices(params, frame, 800, 400);
  EXPECT_TRUE(front.orthographic);
  EXPECT_NEAR(front.forward.z, -1.0f, 1e-6f);  // from the south, looking north
  // West on the left, east on the right, up is up; the whole width and height inside.
  EXPECT_LT(project(front, {0.0, 0.0, 500.0}).x, -0.9);
  EXPECT_GT(project(front, {2000.0, 0.0, 500.0}).x, 0.9);
  EXPECT_GT(project(front, {1000.0, 400.0, 500.0}).y, project(front, {1000.0, -50.0, 500.0}).y);
  for (double x : {0.0, 2000.0})
    for (double y : {-50.0, 400.0}) EXPECT_LE(std::abs(project(front, {x, y, 0.0}).x), 1.0);
  // Depth does not move a point across the picture.
  EXPECT_NEAR(project(front, {700.0, 100.0, 0.0}).x, project(front, {700.0, 100.0, 1000.0}).x, 1e-6);

  params.view = View::side;
  const CameraMatrices side = camera_matrices(params, frame, 800, 400);
  EXPECT_NEAR(side.forward.x, -1.0f, 1e-6f);  // from the east, looking west: north on the right
  EXPECT_GT(project(side, {1000.0, 0.0, 0.0}).x, project(side, {1000.0, 0.0, 1000.0}).x);
  EXPECT_NEAR(project(side, {0.0, 100.0, 300.0}).x, project(side, {2000.0, 100.0, 300.0}).x, 1e-6);
}

TEST(Camera, WalkthroughEyeStandsAboveTheGroundAndLooksAlongItsBearing) {
  const TerrainFrame frame{1000.0, 1000.0, -40.0, 300.0, 50.0, {}, 120.0};
  RenderParams params;
  params.camera.eye_height_m = 1.7;
  params.camera.target_x = 0.25;
  params.camera.target_y = 0.75;
  params.camera.azimuth_deg = 90.0;  // looking east
  params.camera.elevation_deg = -10.0;
  params.validate();
  const CameraMatrices camera = camera_matrices(params, frame, 1280, 720);
  EXPECT_FALSE(camera.orthographic);
  EXPECT_TRUE(camera.walking);
  EXPECT_NEAR(camera.position.x, 250.0f, 1e-3f);
  EXPECT_NEAR(camera.position.z, 750.0f, 1e-3f);
  EXPECT_NEAR(camera.position.y, 121.7f, 1e-3f);
  EXPECT_GT(camera.forward.x, 0.95f);
  EXPECT_LT(camera.forward.y, 0.0f);
  // A point ahead at eye height but slightly down is in the picture's centre band.
  const glm::dvec2 ahead = project(camera, glm::dvec3(camera.position) + 100.0 * glm::dvec3(camera.forward));
  EXPECT_NEAR(ahead.x, 0.0, 1e-4);
  EXPECT_NEAR(ahead.y, 0.0, 1e-4);
  // An orbiting camera may not look up from below its target.
  params.camera.eye_height_m.reset();
  EXPECT_THROW(params.validate(), InputError);
}

}  // namespace
}  // namespace sansui::look

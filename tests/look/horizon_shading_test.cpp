#include "look/horizon_shading.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace sansui::look {
namespace {

Heightfield flat(int size, float height = 100.0f) {
  return Heightfield(size, size, height, 10.0);
}

/// A square tower of `height` metres on flat ground, covering samples [x0, x1) x [y0, y1).
Heightfield tower(int size, int x0, int x1, int y0, int y1, float height) {
  Heightfield heights = flat(size, 0.0f);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) heights(x, y) = height;
  return heights;
}

TEST(SunVisibility, FlatGroundIsLitEverywhereForAnySun) {
  for (double azimuth : {0.0, 45.0, 135.0, 200.0, 300.0})
    for (double elevation : {5.0, 30.0, 89.0}) {
      const Grid<float> lit = sun_visibility(flat(33), {azimuth, elevation, 1.0, 1.0});
      for (float value : lit.values()) ASSERT_FLOAT_EQ(value, 1.0f) << azimuth << " " << elevation;
    }
}

TEST(SunVisibility, ATowerCastsAShadowAwayFromTheSunOfTheRightLength) {
  // Sun in the west (azimuth 270) at 45 degrees: a 100 m tower casts a 100 m = 10 sample
  // shadow to the east; nothing west of it is shaded.
  const Heightfield heights = tower(81, 30, 35, 30, 51, 100.0f);
  const Grid<float> lit = sun_visibility(heights, {270.0, 45.0, 1.0, 0.5});
  const int y = 40;
  for (int x = 0; x < 35; ++x) EXPECT_GT(lit(x, y), 0.99f) << x;
  for (int x = 36; x <= 43; ++x) EXPECT_LT(lit(x, y), 0.01f) << x;  // the shadow, 10 samples long
  for (int x = 47; x < 81; ++x) EXPECT_GT(lit(x, y), 0.99f) << x;
  // Rows beyond the tower's north and south ends stay lit.
  for (int x = 0; x < 81; ++x) EXPECT_GT(lit(x, 20), 0.99f);
}

TEST(SunVisibility, ShadowFollowsTheSunAroundTheCompass) {
  const Heightfield heights = tower(61, 28, 33, 28, 33, 80.0f);
  struct Case {
    double azimuth;
    int dx, dy;  // the direction the shadow falls, in grid steps (x east, y south)
  };
  for (const Case& c : {Case{0, 0, 1}, Case{90, -1, 0}, Case{180, 0, -1}, Case{270, 1, 0}, Case{315, 1, 1}}) {
    const Grid<float> lit = sun_visibility(heights, {c.azimuth, 30.0, 1.0, 0.5});
    EXPECT_LT(lit(30 + 5 * c.dx, 30 + 5 * c.dy), 0.05f) << "sun at " << c.azimuth;  // behind the tower
    EXPECT_GT(lit(30 - 5 * c.dx, 30 - 5 * c.dy), 0.95f) << "sun at " << c.azimuth;  // in front of it
  }
}

TEST(SunVisibility, VerticalScaleLengthensShadows) {
  const Heightfield heights = tower(81, 30, 35, 30, 51, 50.0f);
  const Grid<float> plain = sun_visibility(heights, {270.0, 45.0, 1.0, 0.5});
  const Grid<float> doubled = sun_visibility(heights, {270.0, 45.0, 2.0, 0.5});
  EXPECT_GT(plain(42, 40), 0.99f);    // 5 samples of shadow at scale 1 ...
  EXPECT_LT(doubled(42, 40), 0.01f);  // ... 10 at scale 2
}

TEST(SunVisibility, PenumbraIsSoftAndStaysInRange) {
  const Heightfield heights = tower(81, 30, 35, 30, 51, 100.0f);
  const Grid<float> lit = sun_visibility(heights, {270.0, 30.0, 1.0, 3.0});
  int partial = 0;
  for (float value : lit.values()) {
    ASSERT_GE(value, 0.0f);
    ASSERT_LE(value, 1.0f);
    partial += (value > 0.05f && value < 0.95f) ? 1 : 0;
  }
  EXPECT_GT(partial, 10);  // a soft edge, not a hard one
}

TEST(AmbientOcclusion, FlatGroundIsFullyOpen) {
  const Grid<float> open = ambient_occlusion(flat(40), {});
  for (float value : open.values()) ASSERT_FLOAT_EQ(value, 1.0f);
}

TEST(AmbientOcclusion, APitBetween45DegreeWallsSeesHalfTheSky) {
  // A V-shaped pit whose sides rise at 45 degrees in every direction (a cone upside down): the
  // horizon stands at 45 degrees all round, and cos^2(45) = 0.5.
  Heightfield heights(65, 65, 0.0f, 1.0);
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) heights(x, y) = static_cast<float>(std::max(std::abs(x - 32), std::abs(y - 32)));
  const Grid<float> open = ambient_occlusion(heights, {1.0, 16});
  // Along the axes the walls rise 1 per sample; along diagonals 1 per sqrt(2) samples' distance.
  const double axis = 0.5, diagonal = 1.0 / 3.0;  // sin^2 of atan(1) and of atan(1/sqrt 2)
  EXPECT_NEAR(open(32, 32), 1.0 - (4 * axis + 4 * diagonal) / 8.0, 1e-5);
  // A peak sees the whole sky.
  Heightfield peak = heights;
  for (float& value : peak.values()) value = -value;
  EXPECT_FLOAT_EQ(ambient_occlusion(peak, {1.0, 16})(32, 32), 1.0f);
}

TEST(AmbientOcclusion, HollowsAreDarkerThanRidges) {
  Heightfield heights(64, 64, 0.0f, 10.0);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) heights(x, y) = static_cast<float>(60.0 * std::sin(x * 2.0 * std::numbers::pi / 32.0));
  const Grid<float> open = ambient_occlusion(heights, {1.0, 16});
  EXPECT_LT(open(24, 32), open(8, 32));  // trough at x = 24, crest at x = 8
  for (float value : open.values()) {
    ASSERT_GE(value, 0.0f);
    ASSERT_LE(value, 1.0f);
  }
}

}  // namespace
}  // namespace sansui::look

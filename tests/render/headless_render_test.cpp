// The headless renderer in CI: no DISPLAY, an EGL surfaceless context on Mesa's llvmpipe.
#include <cmath>
#include <cstdlib>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "render/render_image.hpp"
#include "terrain/midpoint.hpp"
#include "tests/render/render_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui::render {

using namespace look;  // the look this file draws: params, layers, plant levels of detail
namespace {

using test::island;
using test::render_headless;

std::uint64_t hash_of(const Image& image) {
  return test::fnv1a(image.data(), image.size() * sizeof(Rgba8));
}

bool bluish(const Rgba8& c) {
  return c.b > c.r + 30 && c.b >= c.g;
}
bool greenish(const Rgba8& c) {
  return c.g > c.r && c.g > c.b;
}

RenderParams small(View view) {
  RenderParams params;
  params.view = view;
  params.width = 320;
  params.height = view == View::top ? 320 : 180;
  params.samples = 1;
  return params;
}

TEST(HeadlessRender, BlockViewShowsSkyAboveTerrain) {
  // The block alone in the sky (world_view_test.cpp has the terrain in its world).
  const Image image = render_headless(island(), small(View::block));
  ASSERT_EQ(image.width(), 320);
  ASSERT_EQ(image.height(), 180);
  // Sky along the top rows: bluish, and a gradient (lighter toward the horizon).
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < image.width(); ++x) ASSERT_TRUE(bluish(image(x, y))) << x << "," << y;
  EXPECT_GT(image(160, 40).r, image(160, 0).r);
  // Terrain below: forest greens make up a good part of the picture, and many colours.
  int green = 0;
  std::set<std::uint32_t> colours;
  for (const Rgba8& c : image.values()) {
    green += greenish(c) ? 1 : 0;
    colours.insert(static_cast<std::uint32_t>(c.r) << 16 | static_cast<std::uint32_t>(c.g) << 8 | c.b);
  }
  EXPECT_GT(green, image.width() * image.height() / 20);
  EXPECT_GT(colours.size(), 2000u);
  // Down the middle column: sky first, then terrain below it.
  int first_terrain_row = -1;
  for (int y = 0; y < image.height() && first_terrain_row < 0; ++y)
    if (!bluish(image(160, y)) || greenish(image(160, y))) first_terrain_row = y;
  EXPECT_GT(first_terrain_row, 10);
  EXPECT_LT(first_terrain_row, 120);
}

/// A round mountain rising from the sea: 1480 m above sea level at the centre, sea in the corners.
Heightfield mountain() {
  Heightfield heights(129, 129, 0.0f, 100.0);
  for (int y = 0; y < 129; ++y)
    for (int x = 0; x < 129; ++x) {
      const double r = std::hypot(x - 64.0, y - 64.0) / 30.0;
      heights(x, y) = static_cast<float>(1600.0 * std::exp(-r * r) - 120.0);
    }
  return heights;
}

/// The lines of a cold place: forest to 900 m, snow from 1,100 m (a 1,480 m peak holds snow).
RenderParams cold(RenderParams params) {
  params.land.tree_line_m = 900.0;
  params.land.snow_line_m = 1100.0;
  return params;
}

TEST(HeadlessRender, TopViewHasSnowOnThePeakForestOnTheSlopesAndSeaInTheCorners) {
  const Image image = render_headless(mountain(), cold(small(View::top)));
  const Rgba8 peak = image(160, 160), slope = image(160 + 82, 160), sea = image(8, 8);
  EXPECT_GT(std::min({peak.r, peak.g, peak.b}), 170) << "peak " << int(peak.r) << "," << int(peak.g) << "," << int(peak.b);
  EXPECT_TRUE(greenish(slope)) << "slope " << int(slope.r) << "," << int(slope.g) << "," << int(slope.b);
  EXPECT_TRUE(bluish(sea)) << "sea " << int(sea.r) << "," << int(sea.g) << "," << int(sea.b);
  // Shadows: with the sun in the west-north-west, the east-south-east flank is darker than the
  // west-north-west one at the same elevation.
  const Rgba8 lit = image(160 - 60, 160 - 25), shaded = image(160 + 60, 160 + 25);
  EXPECT_GT(lit.r + lit.g + lit.b, shaded.r + shaded.g + shaded.b + 30);
}

/// Near-white pixels: the snow band's colour (sunlit).
int snowy_pixels(const Image& image) {
  int count = 0;
  for (const Rgba8& c : image.values()) count += std::min({c.r, c.g, c.b}) > 170 ? 1 : 0;
  return count;
}

// With Table 4's lines (lines = "paper") the bands follow the data, yet a 100-200 m hill by the
// sea (a 94-195 m volcano) is not painted as rock and snow: the bands are fractions of at least
// min_band_relief_m.
TEST(HeadlessRender, ALowHillGetsNoSnowWhileAMountainOfTheSameShapeDoes) {
  Heightfield hill(129, 129, 0.0f, 10.0), mountain(129, 129, 0.0f, 100.0);
  for (int y = 0; y < 129; ++y)
    for (int x = 0; x < 129; ++x) {
      const double r = std::hypot(x - 64.0, y - 64.0) / 40.0, bump = std::exp(-r * r);
      hill(x, y) = static_cast<float>(100.0 + 100.0 * bump);
      mountain(x, y) = static_cast<float>(1000.0 + 1000.0 * bump);
    }
  Land paper;
  paper.lines = LandLines::paper;
  EXPECT_DOUBLE_EQ(band_scale_m(paper, 0.0, 200.0), min_band_relief_m);
  EXPECT_DOUBLE_EQ(band_scale_m(paper, 0.0, 2000.0), 2000.0);
  EXPECT_DOUBLE_EQ(band_scale_m(paper, -100.0, 900.0), 1000.0);
  EXPECT_DOUBLE_EQ(band_scale_m(Land{}, -100.0, 900.0), climate_band_scale_m);
  RenderParams params = small(View::top);
  params.land.lines = LandLines::paper;
  EXPECT_EQ(snowy_pixels(render_headless(hill, params)), 0);
  EXPECT_GT(snowy_pixels(render_headless(mountain, params)), 320 * 320 / 50);
  // Without a sea the bands hang on the hill's own lowest point: still no snow.
  RenderParams no_sea = params;
  no_sea.sea = false;
  EXPECT_EQ(snowy_pixels(render_headless(hill, no_sea)), 0);
}

TEST(HeadlessRender, SameInputGivesTheSameBytes) {
  const Heightfield heights = island();
  const Image first = render_headless(heights, small(View::perspective));
  const Image second = render_headless(heights, small(View::perspective));
  EXPECT_EQ(hash_of(first), hash_of(second));
}

TEST(HeadlessRender, SunExaggerationAndShadowsChangeThePicture) {
  const Heightfield heights = island();
  RenderParams params = small(View::top);
  params.sun_elevation_deg = 12.0;
  const auto hash = [&](const RenderParams& p) { return hash_of(render_headless(heights, p)); };
  const auto brightness = [&](const RenderParams& p) {
    long sum = 0;
    const Image image = render_headless(heights, p);
    for (const Rgba8& c : image.values()) sum += c.r + c.g + c.b;
    return sum;
  };
  RenderParams no_shadows = params;
  no_shadows.shadows = false;
  EXPECT_LT(brightness(params), brightness(no_shadows));
  RenderParams exaggerated = params;
  exaggerated.exaggeration = 4.0;
  EXPECT_NE(hash(params), hash(exaggerated));
}

TEST(HeadlessRender, CliffAlbedoReplacesTheCliffColour) {
  // A steep pyramid: every face is cliff (about 63 degrees).
  Heightfield heights(65, 65, 0.0f, 10.0);
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) heights(x, y) = static_cast<float>(20.0 * (32 - std::max(std::abs(x - 32), std::abs(y - 32))));
  const Image red(65, 65, Rgba8{230, 20, 20, 255});
  auto count_red = [](const Image& image) {
    int count = 0;
    for (const Rgba8& c : image.values()) count += (c.r > 2 * c.g && c.r > 2 * c.b) ? 1 : 0;
    return count;
  };
  RenderParams params = small(View::top);
  EXPECT_EQ(count_red(render_headless(heights, params)), 0);
  EXPECT_GT(count_red(render_headless(heights, params, {&red})), 320 * 320 / 4);
}

TEST(HeadlessRender, RiversAndLakesAreDrawnAsWaterWithDarkerWetBanks) {
  // Gentle green land (a slope from 300 m to 100 m) with a river down its middle column band and
  // wet ground beside it.
  Heightfield heights(129, 129, 0.0f, 20.0);
  Grid<float> depth(129, 129, 0.0f), wetness(129, 129, 0.0f);
  for (int y = 0; y < 129; ++y)
    for (int x = 0; x < 129; ++x) {
      heights(x, y) = static_cast<float>(300.0 - 200.0 * y / 128.0);
      const int from_river = std::abs(x - 64);
      if (from_river <= 1) depth(x, y) = 2.0f;
      if (from_river <= 12) wetness(x, y) = 1.0f - static_cast<float>(from_river) / 13.0f;
    }
  RenderParams params = small(View::top);
  params.land.lines = LandLines::paper;
  params.land.tree_line = 0.99;
  params.land.snow_line = 1.0;
  const Image dry = render_headless(heights, params);
  TerrainLayers layers;
  layers.water_depth = &depth;
  layers.wetness = &wetness;
  const Image wet = render_headless(heights, params, layers);
  // The picture is 320 wide over 128 cells: the river (3 samples) is about 7 pixels wide.
  const int mid = wet.height() / 2, centre = wet.width() / 2;
  EXPECT_TRUE(bluish(wet(centre, mid))) << int(wet(centre, mid).r) << "," << int(wet(centre, mid).g) << "," << int(wet(centre, mid).b);
  EXPECT_FALSE(bluish(dry(centre, mid)));
  // A bank a few samples from the river is darker than the same dry ground; far land unchanged.
  const int bank = centre + 12;
  auto grey = [](const Rgba8& c) { return c.r + c.g + c.b; };
  EXPECT_LT(grey(wet(bank, mid)), grey(dry(bank, mid)) - 15);
  EXPECT_NEAR(grey(wet(10, mid)), grey(dry(10, mid)), 3);
}

TEST(HeadlessRender, BigHeightfieldsAreAveragedDown) {
  // 513^2 with a texture cap of 129: the picture still shows the mountain.
  Heightfield heights(513, 513, 0.0f, 25.0);
  for (int y = 0; y < 513; ++y)
    for (int x = 0; x < 513; ++x) {
      const double r = std::hypot(x - 256.0, y - 256.0) / 120.0;
      heights(x, y) = static_cast<float>(1600.0 * std::exp(-r * r) - 120.0);
    }
  RenderParams params = cold(small(View::top));
  params.max_texture_samples = 129;
  params.max_mesh_samples = 65;
  const Image image = render_headless(heights, params);
  EXPECT_GT(std::min({image(160, 160).r, image(160, 160).g, image(160, 160).b}), 170);
  EXPECT_TRUE(bluish(image(8, 8)));
}

TEST(HeadlessRender, BadHeightsAreRefusedWithAMessage) {
  Heightfield heights = mountain();
  heights(3, 5) = std::nanf("");
  try {
    render_headless(heights, small(View::top));
    FAIL() << "a NaN height was accepted";
  } catch (const InputError& error) {
    EXPECT_THAT(error.what(), ::testing::HasSubstr("height nan at sample (3, 5) is not allowed"));
  }
  EXPECT_THROW(render_headless(Heightfield(1, 5, 0.0f), small(View::top)), InputError);
  RenderParams bad = small(View::top);
  bad.width = 3;
  EXPECT_THROW(render_headless(mountain(), bad), InputError);
}

}  // namespace
}  // namespace sansui::render

// The sky as it is drawn, measured on rendered pixels: darker at night than by day at the top
// of the picture, redder near the horizon toward a setting sun than at noon; stars only at night.
#include <cstdlib>

#include <gtest/gtest.h>

#include "look/sky_dome.hpp"
#include "render/render_image.hpp"
#include "terrain/midpoint.hpp"

namespace sansui::render {

using namespace look;  // the look this file draws: params, layers, plant levels of detail
namespace {

/// A low, small terrain in the lower part of the picture and the sky above it, looking toward
/// the sun's azimuth.
Image sky_picture(double sun_elevation_deg, SkyModel model) {
  ::unsetenv("DISPLAY");
  terrain::MidpointParams midpoint;
  midpoint.seed = 3;
  midpoint.sigma_m = 20.0;
  Heightfield heights = terrain::generate_midpoint(midpoint, 65);
  heights.cell_size_m = 100.0;
  RenderParams params;
  params.width = 160;
  params.height = 120;
  params.samples = 1;
  params.sun_azimuth_deg = 270.0;
  params.sun_elevation_deg = sun_elevation_deg;
  params.camera.azimuth_deg = 90.0;  // standing east of the terrain, looking west into the sun
  params.camera.elevation_deg = 5.0;
  params.sky.model = model;
  params.sky.cloud_cover = 0.0;
  return render_image(heights, params);
}

double luminance(const Rgba8& c) {
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}
double red_over_blue(const Rgba8& c) {
  return (c.r + 1.0) / (c.b + 1.0);
}

/// Mean over a band of rows near the top or just above the terrain, across the middle.
Rgba8 mean_colour(const Image& image, int y0, int y1) {
  double r = 0, g = 0, b = 0, n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = image.width() / 4; x < 3 * image.width() / 4; ++x) r += image(x, y).r, g += image(x, y).g, b += image(x, y).b, ++n;
  return {static_cast<std::uint8_t>(r / n), static_cast<std::uint8_t>(g / n), static_cast<std::uint8_t>(b / n), 255};
}

class SkyRender : public ::testing::TestWithParam<SkyModel> {};

TEST_P(SkyRender, TheTopIsDarkerAtNightThanByDay) {
  const Image day = sky_picture(60.0, GetParam()), night = sky_picture(-18.0, GetParam());
  const double day_top = luminance(mean_colour(day, 0, 10)), night_top = luminance(mean_colour(night, 0, 10));
  EXPECT_GT(day_top, 100.0);
  EXPECT_LT(night_top, 40.0);
  EXPECT_GT(day_top, 4.0 * night_top);
}

TEST_P(SkyRender, TheHorizonTowardASettingSunIsRedderThanAtNoon) {
  const Image sunset = sky_picture(1.0, GetParam()), noon = sky_picture(60.0, GetParam());
  // Rows just above the terrain's far edge (the terrain fills the lower part of the picture).
  const Rgba8 low_sunset = mean_colour(sunset, 40, 55), low_noon = mean_colour(noon, 40, 55);
  EXPECT_GT(red_over_blue(low_sunset), 1.2 * red_over_blue(low_noon));
  EXPECT_GT(red_over_blue(low_sunset), 1.0);  // warmer than it is blue
}

INSTANTIATE_TEST_SUITE_P(Models, SkyRender, ::testing::Values(SkyModel::preetham, SkyModel::table2),
                         [](const auto& test) { return std::string(sky_model_name(test.param)); });

TEST(SkyDome, StarsShowOnlyAtNightAndFollowTheSeed) {
  RenderParams params = with_fallbacks({});
  params.sun_elevation_deg = -30.0;
  auto brightest_texel = [](const SkyDome& dome) {
    float best = 0.0f;
    for (std::size_t i = 0; i < dome.rgba.size(); i += 4) best = std::max(best, dome.rgba[i + 2]);
    return best;
  };
  const SkyDome night = bake_sky_dome(params, nullptr, 512, 128);
  params.sky.stars = false;
  const SkyDome starless = bake_sky_dome(params, nullptr, 512, 128);
  EXPECT_GT(brightest_texel(night), 3.0f * brightest_texel(starless));
  params.sky.stars = true;
  params.sun_elevation_deg = 40.0;
  const SkyDome day = bake_sky_dome(params, nullptr, 512, 128);
  params.sky.stars = false;
  EXPECT_EQ(day.rgba, bake_sky_dome(params, nullptr, 512, 128).rgba);  // no stars by day
  params.sky.stars = true;
  params.sun_elevation_deg = -30.0;
  EXPECT_EQ(night.rgba, bake_sky_dome(params, nullptr, 512, 128).rgba);  // the same seed, the same sky
  params.sky.seed = 2;
  EXPECT_NE(night.rgba, bake_sky_dome(params, nullptr, 512, 128).rgba);
}

TEST(SkyDome, CloudsCoverWhatTheirCoverSays) {
  terrain::MidpointParams midpoint;
  midpoint.sigma_m = 1.0;
  const Heightfield image = terrain::generate_midpoint(midpoint, 129);
  for (double cover : {0.0, 0.3, 0.7, 1.0}) {
    const Grid<float> density = cloud_density(image, cover);
    double covered = 0.0;
    for (float d : density.values()) covered += d > 0.5f;
    EXPECT_NEAR(covered / static_cast<double>(density.size()), cover, 0.05) << cover;
  }
}

}  // namespace
}  // namespace sansui::render

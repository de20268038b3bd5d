// The sky as it is drawn, measured on rendered pixels: darker at night than by day at the top
// of the picture, redder near the horizon toward a setting sun than at noon; stars only at night.
// Clouds and sea: smooth clouds, thick ones darker, their shadows on the land, a sea without a
// repeating tile and a shore without bright specks.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "look/sky_dome.hpp"
#include "render/render_image.hpp"
#include "terrain/midpoint.hpp"
#include "tests/test_util.hpp"

namespace sansui::render {

using namespace look;  // the look this file draws: params, layers, plant levels of detail
namespace {

/// A low, small terrain in the lower part of the picture and the sky above it, looking toward
/// the sun's azimuth.
Image sky_picture(double sun_elevation_deg, SkyModel model, int width = 160, int height = 120, int samples = 1, bool stars = true) {
  ::unsetenv("DISPLAY");
  terrain::MidpointParams midpoint;
  midpoint.seed = 3;
  midpoint.sigma_m = 20.0;
  Heightfield heights = terrain::generate_midpoint(midpoint, 65);
  heights.cell_size_m = 100.0;
  RenderParams params;
  params.width = width;
  params.height = height;
  params.samples = samples;
  params.sky.stars = stars;
  params.sun_azimuth_deg = 270.0;
  params.sun_elevation_deg = sun_elevation_deg;
  params.camera.azimuth_deg = 90.0;  // standing east of the terrain, looking west into the sun
  params.camera.elevation_deg = 5.0;
  params.sky.model = model;
  params.sky.cloud_cover = 0.0;
  // The block view's backdrop spreads the sky from the horizon up to 60 degrees over the
  // picture, so a small picture shows the whole gradient the models make.
  params.view = View::block;
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

/// The patches of pixels brighter than the sky around them (8-connected) in the top third of
/// the picture, each its count of pixels.
std::vector<int> bright_specks(const Image& image, double above) {
  const int w = image.width(), h = image.height() / 3;
  std::vector<double> sky;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) sky.push_back(luminance(image(x, y)));
  std::vector<double> sorted = sky;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  const double background = sorted[sorted.size() / 2];
  std::vector<char> seen(sky.size(), 0);
  std::vector<int> specks;
  for (int start = 0; start < w * h; ++start) {
    if (seen[start] || sky[start] < background + above) continue;
    int pixels = 0;
    std::vector<int> stack{start};
    seen[start] = 1;
    while (!stack.empty()) {
      const int at = stack.back();
      stack.pop_back();
      ++pixels;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int x = at % w + dx, y = at / w + dy;
          if (x < 0 || y < 0 || x >= w || y >= h || seen[y * w + x] || sky[y * w + x] < background + above) continue;
          seen[y * w + x] = 1;
          stack.push_back(y * w + x);
        }
    }
    specks.push_back(pixels);
  }
  return specks;
}

TEST(SkyRender, StarsArePointsOfAPixelAtThePicturesResolution) {
  // Issue 49: baked into the sky dome, a star was a soft blob of a texel, 4-6 pixels wide in a
  // picture of 1280 pixels. Drawn as points, nearly every star is one pixel, or two or three
  // where antialiasing shares it out.
  const std::vector<int> stars = bright_specks(sky_picture(-30.0, SkyModel::preetham, 640, 480, 4), 20.0);
  ASSERT_GT(stars.size(), 30u);
  const auto small = std::count_if(stars.begin(), stars.end(), [](int pixels) { return pixels <= 4; });
  EXPECT_GT(static_cast<double>(small), 0.95 * static_cast<double>(stars.size()));
  EXPECT_TRUE(bright_specks(sky_picture(-30.0, SkyModel::preetham, 640, 480, 4, false), 20.0).empty());
  RecordProperty("stars", static_cast<int>(stars.size()));
}

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

/// A cloud layer: the paper's midpoint image at `cover` (as scene_clouds() makes it).
Grid<float> clouds_of(double cover, std::uint64_t seed = 5) {
  terrain::MidpointParams midpoint;
  midpoint.seed = seed;
  midpoint.hurst = 0.5;
  midpoint.sigma_m = 1.0;
  midpoint.paper_sea_level = true;
  return cloud_density(terrain::generate_midpoint(midpoint, 257), cover);
}

/// A low island (seed 1 has sea on two sides) 10 km across, small pictures.
Heightfield low_island() {
  terrain::MidpointParams midpoint;
  midpoint.seed = 1;
  midpoint.sigma_m = 150.0;
  Heightfield heights = terrain::generate_midpoint(midpoint, 129);
  heights.cell_size_m = 80.0;
  return heights;
}

RenderParams cloudy_params(double cover) {
  RenderParams params;
  params.width = 320;
  params.height = 180;
  params.samples = 1;
  params.sun_azimuth_deg = 150.0;
  params.sun_elevation_deg = 40.0;
  params.sky.cloud_cover = cover;
  return params;
}

/// A walker on the island looking along the sky, pitched up: the picture is mostly sky.
Image walker_sky(const Grid<float>* clouds, double cover, double pitch_deg) {
  ::unsetenv("DISPLAY");
  RenderParams params = cloudy_params(cover);
  params.camera.eye_height_m = 40.0;
  params.camera.elevation_deg = pitch_deg;
  params.camera.azimuth_deg = 330.0;  // away from the sun
  params.camera.fov_deg = 60.0;
  TerrainLayers layers;
  layers.clouds = clouds;
  return render_image(low_island(), params, layers);
}

double mean_luminance(const Image& image, int y0, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < image.width(); ++x) sum += luminance(image(x, y));
  return sum / ((y1 - y0) * image.width());
}

TEST(Clouds, AreSmoothFromOverheadToTheHorizon) {
  const Grid<float> clouds = clouds_of(0.5);
  const Image image = walker_sky(&clouds, 0.5, 25.0);
  // The sky fills the picture above the land: the rows whose every pixel is sky-coloured
  // (not green) from the top down. Cloud edges are soft: no step between neighbouring pixels
  // is large, and large steps are rare (a stair-stepped or blocky dome shows many).
  int sky_rows = 0;
  for (int y = 0; y < image.height(); ++y) {
    bool sky = true;
    for (int x = 0; x < image.width() && sky; ++x) sky = !(image(x, y).g > image(x, y).r + 10 && image(x, y).g > image(x, y).b + 10);
    if (!sky) break;
    ++sky_rows;
  }
  ASSERT_GT(sky_rows, image.height() / 2);
  double largest = 0.0, steps = 0.0, big = 0.0, spread = 0.0;
  for (int y = 1; y < sky_rows - 2; ++y)
    for (int x = 1; x < image.width(); ++x) {
      const double here = luminance(image(x, y));
      for (double step : {std::abs(here - luminance(image(x - 1, y))), std::abs(here - luminance(image(x, y - 1)))}) {
        largest = std::max(largest, step);
        big += step > 12.0 ? 1.0 : 0.0;
        steps += 1.0;
      }
      spread = std::max(spread, std::abs(here - luminance(image(0, 0))));
    }
  EXPECT_GT(spread, 20.0);  // there are clouds to see
  EXPECT_LT(largest, 24.0);
  EXPECT_LT(big / steps, 0.003);
}

// Issue 49: the haze band at the horizon. Over an open sea under clouds, looking level, the
// 5 degrees above the horizon have no vertical stripes (no column differs from its neighbour by
// more than 2 levels) and no line across (no row from the next by more than 2.5 levels on
// average); the sea below is darker than the sky above its horizon.
TEST(Clouds, TheSkyAboveTheHorizonHasNoStripesAndNoLine) {
  ::unsetenv("DISPLAY");
  const Grid<float> clouds = clouds_of(0.5);
  RenderParams params = cloudy_params(0.5);
  params.camera.eye_height_m = 40.0;
  params.camera.elevation_deg = 0.0;
  params.camera.azimuth_deg = 330.0;
  params.camera.fov_deg = 60.0;  // 180 rows: 3 rows a degree, the horizon at row 90
  TerrainLayers layers;
  layers.clouds = &clouds;
  Heightfield sea(129, 129, -50.0f);
  sea.cell_size_m = 80.0;
  const Image image = render_image(sea, params, layers);
  const int horizon = image.height() / 2, band_top = horizon - 15;
  const auto row_mean = [&](int y) {
    double sum = 0.0;
    for (int x = 0; x < image.width(); ++x) sum += luminance(image(x, y));
    return sum / image.width();
  };
  for (int y = band_top; y < horizon - 1; ++y) {
    int widest = 0;
    for (int x = 1; x < image.width(); ++x)
      for (int channel = 0; channel < 3; ++channel) {
        const auto value = [&](int at) { return channel == 0 ? image(at, y).r : channel == 1 ? image(at, y).g : image(at, y).b; };
        widest = std::max(widest, std::abs(value(x) - value(x - 1)));
      }
    EXPECT_LE(widest, 2) << "row " << y;
    // A line is a step that stands out of the sky's gradient: larger than its neighbours' by
    // more than 2.5 levels.
    const auto step = [&](int at) { return std::abs(row_mean(at) - row_mean(at + 1)); };
    if (y > band_top) {
      EXPECT_LE(step(y) - std::max(step(y - 1), step(y + 1)), 2.5) << "row " << y;
    }
  }
  EXPECT_LT(row_mean(horizon + 3), row_mean(horizon - 3) - 5.0);
}

TEST(Clouds, ThickCloudsAreDarkerUnderneath) {
  // The same full cover, once just at the edge's value (thin) and once far above it (thick).
  Grid<float> thin(129, 129, 1.0f), thick(129, 129, cloud_density_max);
  const Image thin_image = walker_sky(&thin, 1.0, 50.0), thick_image = walker_sky(&thick, 1.0, 50.0);
  const double thin_sky = mean_luminance(thin_image, 0, 60), thick_sky = mean_luminance(thick_image, 0, 60);
  EXPECT_LT(thick_sky, 0.9 * thin_sky);
  EXPECT_GT(thick_sky, 20.0);  // grey, not black
}

TEST(Clouds, OpticalDepthIsLargestInTheMiddleOfABigCloud) {
  Grid<float> density(64, 64, 0.0f);
  for (int y = 8; y < 56; ++y)
    for (int x = 8; x < 40; ++x) density(x, y) = cloud_density_max;  // a big cloud
  density(52, 32) = 1.0f;                                            // a wisp
  const Grid<float> depth = cloud_thickness(density, 4);
  EXPECT_GT(depth(24, 32), 0.9f);
  EXPECT_LT(depth(8, 32), 0.75f * depth(24, 32));  // its edge
  EXPECT_LT(depth(52, 32), 0.05f);
  EXPECT_EQ(depth(60, 60), 0.0f);  // clear sky
}

/// The island from above (the top view: the land and sea only), with or without a cloud layer.
Image island_from_above(const Grid<float>* clouds) {
  ::unsetenv("DISPLAY");
  RenderParams params = cloudy_params(0.5);
  params.view = View::top;
  params.height = 320;
  TerrainLayers layers;
  layers.clouds = clouds;
  return render_image(low_island(), params, layers);
}

TEST(Clouds, CastShadowsOnTheLand) {
  const Grid<float> clouds = clouds_of(0.5);
  const Image clear = island_from_above(nullptr), cloudy = island_from_above(&clouds);
  // Land pixels (green in the clear picture), each as bright under the clouds as in the clear
  // picture over the sunlit tenth (white clouds lighten the sky's light a little): a good share
  // is much darker, in the clouds' shadows, and some land stays in the sun.
  std::vector<double> ratios;
  for (int y = 0; y < clear.height(); ++y)
    for (int x = 0; x < clear.width(); ++x) {
      const Rgba8 c = clear(x, y);
      if (c.g > c.b && c.g >= c.r) ratios.push_back(luminance(cloudy(x, y)) / std::max(luminance(c), 1.0));
    }
  ASSERT_GT(ratios.size(), static_cast<std::size_t>(clear.width() * clear.height() / 5));
  std::sort(ratios.begin(), ratios.end());
  const double sunlit = ratios[ratios.size() * 9 / 10];
  const auto shaded = static_cast<double>(std::count_if(ratios.begin(), ratios.end(), [&](double r) { return r < 0.8 * sunlit; }));
  EXPECT_GT(shaded / static_cast<double>(ratios.size()), 0.15);
  EXPECT_LT(shaded / static_cast<double>(ratios.size()), 0.9);
}

TEST(Clouds, TheSameCloudsGiveTheSameBytes) {
  const Grid<float> clouds = clouds_of(0.5);
  const Image first = walker_sky(&clouds, 0.5, 10.0), second = walker_sky(&clouds, 0.5, 10.0);
  EXPECT_EQ(test::fnv1a(first.data(), first.size() * sizeof(Rgba8)), test::fnv1a(second.data(), second.size() * sizeof(Rgba8)));
  const Grid<float> other = clouds_of(0.5, 6);
  const Image third = walker_sky(&other, 0.5, 10.0);
  EXPECT_NE(test::fnv1a(first.data(), first.size() * sizeof(Rgba8)), test::fnv1a(third.data(), third.size() * sizeof(Rgba8)));
}

/// Normalised autocorrelation of the luminance's detail (less its mean over 9 x 9 pixels, so
/// that the sky's smooth gradient in the reflection does not count) over a w x h window at a
/// shift of (dx, dy) pixels.
double autocorrelation(const Image& image, int x0, int y0, int w, int h, int dx, int dy) {
  const auto detail = [&](int x, int y) {
    double sum = 0.0;
    for (int j = -4; j <= 4; ++j)
      for (int i = -4; i <= 4; ++i) sum += luminance(image(x + i, y + j));
    return luminance(image(x, y)) - sum / 81.0;
  };
  double covariance = 0.0, variance = 0.0;
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x) {
      const double a = detail(x, y), b = detail(x + dx, y + dy);
      covariance += a * b;
      variance += a * a;
    }
  return covariance / std::max(variance, 1e-9);
}

TEST(Sea, RipplesDoNotRepeat) {
  ::unsetenv("DISPLAY");
  // Open sea 3 km across (the old noise tile repeated every 23rd of it, 130 m), seen from a
  // boat 40 m up: no horizontal shift brings the pattern of the near rows back onto itself (a
  // repeating tile would at its period), and there is something to see.
  Heightfield sea(65, 65, -40.0f, 3000.0 / 64);
  RenderParams params = cloudy_params(0.0);
  params.width = 480;
  params.height = 270;
  params.water.ripple = 2.0;
  params.camera.eye_height_m = 40.0;
  params.camera.elevation_deg = -20.0;
  params.camera.azimuth_deg = 10.0;
  params.camera.fov_deg = 60.0;
  const Image image = render_image(sea, params);
  double low = 255.0, high = 0.0;
  for (int y = 150; y < 260; ++y)
    for (int x = 100; x < 380; ++x) low = std::min(low, luminance(image(x, y))), high = std::max(high, luminance(image(x, y)));
  EXPECT_GT(high - low, 4.0);
  // Past the shift where neighbouring detail stops being alike, the correlation stays low: a
  // tile would bring it back up at its period.
  double highest = -1.0;
  int at = 0;
  bool apart = false;
  for (int shift = 2; shift <= 120; ++shift) {
    const double correlation = autocorrelation(image, 100, 120, 200, 100, shift, 0);
    if (!apart) {
      apart = correlation < 0.1;
      continue;
    }
    if (correlation > highest) highest = correlation, at = shift;
  }
  EXPECT_TRUE(apart);
  EXPECT_LT(highest, 0.3) << "at a shift of " << at << " pixels";
}

/// Pixels much brighter than every neighbour (specks of foam, glints or reflections a pixel wide).
int bright_specks(const Image& image, std::string& where) {
  int specks = 0;
  for (int y = 1; y < image.height() - 1; ++y)
    for (int x = 1; x < image.width() - 1; ++x) {
      const double here = luminance(image(x, y));
      double brightest_neighbour = 0.0;
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i)
          if (i != 0 || j != 0) brightest_neighbour = std::max(brightest_neighbour, luminance(image(x + i, y + j)));
      if (here > brightest_neighbour + 25.0) {
        ++specks;
        where += " (" + std::to_string(x) + "," + std::to_string(y) + ")";
      }
    }
  return specks;
}

TEST(Sea, TheShoreHasNoBrightSpecks) {
  ::unsetenv("DISPLAY");
  // The island in perspective with sun and clouds over the sea: pixels much brighter than
  // every neighbour are all but absent.
  const Grid<float> clouds = clouds_of(0.5);
  RenderParams params = cloudy_params(0.5);
  params.width = 480;
  params.height = 270;
  params.camera.azimuth_deg = 150.0;  // toward the sun's glint
  params.camera.elevation_deg = 20.0;
  params.water.foam_depth_m = 2.0;
  TerrainLayers layers;
  layers.clouds = &clouds;
  // The terrain's own shores, alone in the block view. Known (issue 31's note): the narrow sand
  // band (5 m) leaves about 6 single sand pixels along these shores (in 130,000), from 22 before
  // it was faded by the pixel's height range; the bound keeps them from growing.
  params.view = View::block;
  std::string where;
  EXPECT_LE(bright_specks(render_image(low_island(), params, layers), where), 8) << where;
  // In its world. Known (issue 31's note): about 25 single pixels (in 130,000) still show on the
  // surroundings' distant land, whose coarse grid and mirrored surface disagree; this bound
  // keeps them from growing.
  params.view = View::perspective;
  where.clear();
  EXPECT_LE(bright_specks(render_image(low_island(), params, layers), where), 30) << where;
}

}  // namespace
}  // namespace sansui::render

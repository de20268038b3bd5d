// The ground's colour rules on pixels (issue 31, "ground that varies"): valley floors greener
// or wetter than the ridges above them, cliffs rock-coloured, no sand above beach height, and
// detail below the grid in a view from eye height.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "render/render_image.hpp"
#include "scene/climate.hpp"
#include "scene/look.hpp"
#include "scene/recipe.hpp"
#include "tests/render/render_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui::render {

using namespace look;
namespace {

using test::render_headless;

RenderParams top_view() {
  RenderParams params;
  params.view = View::top;
  params.width = 320;
  params.height = 320;
  params.samples = 1;
  return params;
}

/// Mean colour over a (2r + 1)^2 window.
struct Mean {
  double r = 0, g = 0, b = 0;
  double greenness() const { return g / std::max(r + g + b, 1.0); }
  double brightness() const { return r + g + b; }
};
Mean mean_around(const Image& image, int cx, int cy, int radius = 3) {
  Mean m;
  int n = 0;
  for (int y = cy - radius; y <= cy + radius; ++y)
    for (int x = cx - radius; x <= cx + radius; ++x, ++n) m.r += image(x, y).r, m.g += image(x, y).g, m.b += image(x, y).b;
  m.r /= n, m.g /= n, m.b /= n;
  return m;
}

/// Ridges at x = 0, 64, 128 and valley floors at x = 32, 96 (100 m of relief), tilted down to
/// the south so that the valleys drain: all of it forest land far below the tree line.
Heightfield ridges_and_valleys() {
  Heightfield heights(129, 129, 0.0f, 20.0);
  for (int y = 0; y < 129; ++y)
    for (int x = 0; x < 129; ++x) heights(x, y) = static_cast<float>(300.0 + 100.0 * std::cos(2.0 * std::numbers::pi * x / 64.0) - 0.5 * y);
  return heights;
}

/// A plane rising 40 degrees to the north, 20 to 450 m above the sea: forest land in every
/// climate but the coldest.
Heightfield forty_degree_face() {
  Heightfield heights(129, 129, 0.0f, 4.0);
  const double rise = std::tan(40.0 * std::numbers::pi / 180.0);
  for (int y = 0; y < 129; ++y)
    for (int x = 0; x < 129; ++x) heights(x, y) = static_cast<float>(20.0 + (128 - y) * 4.0 * rise);
  return heights;
}

// Issue 49: a 40-degree face keeps the climate's plant cover where the climate holds it (Af, Cfb,
// Df) and is bare where it does not (BW, ET). Lighting aside: the face as drawn is compared with
// the same face drawn fully covered (cover_slope 90) and fully bare (cover_slope 0).
TEST(GroundRender, AFortyDegreeFaceIsCoveredInWetClimatesAndBareInDryAndColdOnes) {
  const Heightfield face = forty_degree_face();
  const auto mean_colour = [&](scene::Climate climate, std::optional<double> cover) {
    scene::Recipe recipe;
    recipe.climate.koppen = climate;
    recipe.render = top_view();
    recipe.render.width = 96;
    recipe.render.height = 96;
    recipe.render.shadows = false;
    recipe.render.land.cover_slope_deg = cover;
    scene::resolve_look(recipe);
    return mean_around(render_headless(face, recipe.render), 48, 48, 16);  // the face's middle, away from its edges
  };
  const auto distance = [](const Mean& a, const Mean& b) { return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b); };
  for (const auto& [climate, covered] : std::vector<std::pair<scene::Climate, bool>>{{scene::Climate::Af, true},
                                                                                     {scene::Climate::Cfb, true},
                                                                                     {scene::Climate::Df, true},
                                                                                     {scene::Climate::BW, false},
                                                                                     {scene::Climate::ET, false}}) {
    const Mean drawn = mean_colour(climate, std::nullopt), green = mean_colour(climate, 90.0), bare = mean_colour(climate, 0.0);
    const std::string name(scene::name_of(climate));
    ASSERT_GT(distance(green, bare), 10.0) << name << ": covered and bare must differ to tell them apart";
    if (covered)
      EXPECT_LT(distance(drawn, green), 0.1 * distance(green, bare)) << name;
    else
      EXPECT_LT(distance(drawn, bare), 0.1 * distance(green, bare)) << name;
  }
}

TEST(GroundRender, AValleyFloorIsGreenerOrWetterThanTheRidgeAboveIt) {
  RenderParams params = top_view();
  // Light from high in the south, no shadows or occlusion: the colours are the ground's own.
  params.sun_azimuth_deg = 180.0;
  params.sun_elevation_deg = 70.0;
  params.shadows = false;
  params.ambient_occlusion = 0.0;
  const Image image = render_headless(ridges_and_valleys(), params);
  // 320 pixels over 128 cells: floors at x = 80 and 240, the ridge between at 160.
  for (int y : {120, 200}) {
    const Mean ridge = mean_around(image, 160, y);
    for (int floor_x : {80, 240}) {
      const Mean floor = mean_around(image, floor_x, y);
      const bool greener = floor.greenness() > ridge.greenness() + 0.02;
      const bool wetter = floor.brightness() < ridge.brightness() - 30.0;
      EXPECT_TRUE(greener || wetter) << "floor " << floor.r << "," << floor.g << "," << floor.b << " ridge " << ridge.r << "," << ridge.g
                                     << "," << ridge.b << " at row " << y;
      EXPECT_GT(floor.greenness(), ridge.greenness()) << "row " << y;
    }
  }
}

TEST(GroundRender, ACliffIsRockColoured) {
  // A steep pyramid (63-degree faces) on a 100 m plateau.
  Heightfield heights(65, 65, 0.0f, 10.0);
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) heights(x, y) = static_cast<float>(100.0 + 20.0 * (32 - std::max(std::abs(x - 32), std::abs(y - 32))));
  RenderParams params = top_view();
  params.land.cliff = Rgb{0.55f, 0.50f, 0.45f};
  // The sun straight above: every face gets the same light, so the colours are the rock's own.
  params.sun_elevation_deg = 89.0;
  params.shadows = false;
  const Image image = render_headless(heights, params);
  for (auto [x, y] : {std::pair{100, 160}, {220, 160}, {160, 100}, {160, 220}}) {
    const Mean face = mean_around(image, x, y, 2);
    // Grey-brown: red >= green >= blue (within a little), little saturation, and not green.
    EXPECT_GE(face.r + 4.0, face.g) << x << "," << y;
    EXPECT_GE(face.g + 4.0, face.b) << x << "," << y;
    EXPECT_LT(std::max({face.r, face.g, face.b}) - std::min({face.r, face.g, face.b}), 45.0) << x << "," << y;
  }
}

TEST(GroundRender, NoSandMoreThanAFewMetresAboveTheSea) {
  // A gentle cone island 80 m high (4.6 degrees), its shore 1 km from the centre.
  Heightfield heights(257, 257, 0.0f, 10.0);
  const auto height_at = [](double x_cells, double y_cells) { return 80.0 * (1.0 - std::hypot(x_cells - 128.0, y_cells - 128.0) / 100.0); };
  for (int y = 0; y < 257; ++y)
    for (int x = 0; x < 257; ++x) heights(x, y) = static_cast<float>(height_at(x, y));
  RenderParams params = top_view();
  params.land.beach = Rgb{1.0f, 0.0f, 1.0f};  // magenta sand, to tell it from the green land
  params.land.forest_low = Rgb{0.1f, 0.5f, 0.1f};
  params.land.forest_high = Rgb{0.1f, 0.5f, 0.1f};
  const Image image = render_headless(heights, params);
  int sand_on_beach = 0;
  for (int py = 0; py < image.height(); ++py)
    for (int px = 0; px < image.width(); ++px) {
      const double h = height_at((px + 0.5) * 256.0 / image.width(), (py + 0.5) * 256.0 / image.height());
      const Rgba8 c = image(px, py);
      const bool sandy = c.r > c.g + 40 && c.b > c.g + 40;
      if (h > 10.0) {
        ASSERT_FALSE(sandy) << "sand at " << h << " m (" << px << "," << py << ")";
      }
      if (h > 0.5 && h < 3.0) sand_on_beach += sandy ? 1 : 0;
    }
  EXPECT_GT(sand_on_beach, 200) << "the beach itself is sand";
}

/// A view from eye height over the valleys.
RenderParams ground_view() {
  RenderParams params;
  params.width = 320;
  params.height = 180;
  params.samples = 1;
  params.camera.eye_height_m = 1.7;
  params.camera.target_x = 0.3;
  params.camera.target_y = 0.5;
  params.camera.azimuth_deg = 90.0;
  params.camera.elevation_deg = -12.0;
  return params;
}

TEST(GroundRender, AViewFromEyeHeightHasDetailBelowTheGridAndTheSameBytesTwice) {
  const Heightfield heights = ridges_and_valleys();  // 20 m cells: flat facets without detail
  const Image first = render_headless(heights, ground_view());
  const Image second = render_headless(heights, ground_view());
  EXPECT_EQ(test::fnv1a(first.data(), first.size() * sizeof(Rgba8)), test::fnv1a(second.data(), second.size() * sizeof(Rgba8)));
  // The ground in the lower third: neighbouring pixels differ (texture), not a smooth shade. The
  // grid's own facets, 20 m wide and about 60 pixels across here, change by well under a level
  // per pixel; the detail gave 1.2 levels (summed over r, g, b) when this was written.
  double difference = 0.0;
  int n = 0;
  for (int y = first.height() * 2 / 3; y < first.height(); ++y)
    for (int x = 1; x < first.width(); ++x, ++n) {
      const Rgba8 a = first(x, y), b = first(x - 1, y);
      difference += std::abs(int(a.r) - int(b.r)) + std::abs(int(a.g) - int(b.g)) + std::abs(int(a.b) - int(b.b));
    }
  EXPECT_GT(difference / n, 0.8);
}

}  // namespace
}  // namespace sansui::render

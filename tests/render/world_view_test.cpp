// The perspective view shows the terrain inside its world (issue 31): land or sea across the
// lower part of the picture out to a horizon, never the block's cut sides; view = "block" keeps
// the block.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <gtest/gtest.h>

#include "render/render_image.hpp"
#include "terrain/midpoint.hpp"
#include "tests/render/render_test_util.hpp"
#include "tests/test_util.hpp"

namespace sansui::render {

using namespace look;
namespace {

using test::island;
using test::render_headless;

/// The block's sides in a colour nothing else has.
RenderParams small(View view) {
  RenderParams params;
  params.view = view;
  params.width = 320;
  params.height = 180;
  params.samples = 1;
  params.land.earth = Rgb{1.0f, 0.0f, 1.0f};
  return params;
}

bool magenta(const Rgba8& c) {
  return c.r > 150 && c.b > 150 && c.g < 90;
}
int count_magenta(const Image& image) {
  return static_cast<int>(std::ranges::count_if(image.values(), magenta));
}

/// The share of a row's pixels that look like the daytime sky: light, and all but flat over
/// nine pixels along the row (the sky is a smooth gradient; land is not, and a calm deep sea,
/// as smooth, is dark).
double sky_share(const Image& image, int y) {
  int flat = 0;
  for (int x = 4; x + 4 < image.width(); ++x) {
    int low = 255 * 3, high = 0;
    for (int dx = -4; dx <= 4; ++dx) {
      const Rgba8 c = image(x + dx, y);
      const int sum = c.r + c.g + c.b;
      low = std::min(low, sum), high = std::max(high, sum);
    }
    flat += high - low <= 2 && low > 3 * 140 ? 1 : 0;
  }
  return static_cast<double>(flat) / (image.width() - 8);
}

TEST(WorldView, LandOrSeaFillTheLowerPictureWithoutBlockSides) {
  const Heightfield heights = island();
  for (const double azimuth : {0.0, 135.0, 200.0}) {
    RenderParams params = small(View::perspective);
    params.camera.azimuth_deg = azimuth;
    const Image world = render_headless(heights, params);
    EXPECT_EQ(count_magenta(world), 0) << azimuth;
    for (int y = world.height() * 6 / 10; y < world.height(); ++y) EXPECT_LT(sky_share(world, y), 0.2) << azimuth << " row " << y;
    // The detector sees the sky where the block leaves it.
    params.view = View::block;
    const Image block = render_headless(heights, params);
    EXPECT_GT(count_magenta(block), 200) << azimuth;
    double most_flat = 0.0;
    for (int y = block.height() * 6 / 10; y < block.height(); ++y) most_flat = std::max(most_flat, sky_share(block, y));
    EXPECT_GT(most_flat, 0.2) << azimuth;
  }
}

TEST(WorldView, TheBlockKeepsItsSidesAtEveryElevation) {
  const Heightfield heights = island();
  // From high up the sides are a thin band along the near edges (this block is 10 km wide and
  // a few hundred metres deep: at 60 degrees about a pixel high); still drawn. Straight down
  // (89 degrees) they are edge-on and nothing is asked.
  for (const double elevation : {10.0, 30.0, 60.0}) {
    RenderParams params = small(View::block);
    params.camera.elevation_deg = elevation;
    params.camera.azimuth_deg = 200.0;
    const Image block = render_headless(heights, params);
    EXPECT_GT(count_magenta(block), elevation < 45.0 ? 200 : 40) << elevation << " degrees";
  }
}

TEST(WorldView, AWalkerSeesGroundBelowAndSkyAboveTheHorizon) {
  RenderParams params = small(View::perspective);
  params.camera.eye_height_m = 1.7;
  params.camera.elevation_deg = 0.0;
  params.camera.target_x = 0.5;
  params.camera.target_y = 0.5;
  params.sea = false;  // all land, so the walker looks over ground to the horizon
  const Image image = render_headless(island(), params);
  EXPECT_EQ(count_magenta(image), 0);
  for (int y = image.height() * 7 / 10; y < image.height(); ++y) EXPECT_LT(sky_share(image, y), 0.5) << y;
  // Looking level, the top rows are sky.
  EXPECT_GT(sky_share(image, 2), 0.5);
}

TEST(WorldView, SameSceneSameBytes) {
  const Heightfield heights = island();
  const Image first = render_headless(heights, small(View::perspective));
  const Image second = render_headless(heights, small(View::perspective));
  EXPECT_EQ(test::fnv1a(first.data(), first.size() * sizeof(Rgba8)), test::fnv1a(second.data(), second.size() * sizeof(Rgba8)));
}

}  // namespace
}  // namespace sansui::render

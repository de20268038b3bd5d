#include "look/ground_maps.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "look/surface_maps.hpp"

namespace sansui::look {
namespace {

/// Ridges at x = 0, 64, 128 and valley floors at x = 32, 96 (100 m of relief, 26 degrees at
/// most), all tilted down to the south so that the valleys drain off the map.
Heightfield ridges_and_valleys() {
  Heightfield heights(129, 129, 0.0f, 20.0);
  for (int y = 0; y < 129; ++y)
    for (int x = 0; x < 129; ++x) heights(x, y) = static_cast<float>(300.0 + 100.0 * std::cos(2.0 * std::numbers::pi * x / 64.0) - 0.5 * y);
  return heights;
}

std::uint8_t channel(const std::vector<std::uint8_t>& texels, int width, int x, int y, int c) {
  return texels[(static_cast<std::size_t>(y) * width + x) * 4 + c];
}

TEST(GroundMaps, ValleyFloorsAreWetterAndConcaveRidgesConvex) {
  const Heightfield heights = ridges_and_valleys();
  const std::vector<std::uint8_t> texels = ground_map_texels(heights, {});
  const int w = heights.width();
  for (int y : {64, 100}) {
    EXPECT_GT(channel(texels, w, 32, y, 0), channel(texels, w, 64, y, 0) + 100) << "wetness, row " << y;
    EXPECT_GT(channel(texels, w, 32, y, 1), 160) << "fine curvature on the floor, row " << y;
    EXPECT_LT(channel(texels, w, 64, y, 1), 96) << "fine curvature on the ridge, row " << y;
    EXPECT_GT(channel(texels, w, 32, y, 3), 128) << "broad curvature on the floor, row " << y;
    EXPECT_LT(channel(texels, w, 64, y, 3), 128) << "broad curvature on the ridge, row " << y;
  }
  EXPECT_EQ(texels, ground_map_texels(heights, {}));
}

TEST(GroundMaps, ScreeLiesAtTheFootOfACliffNotOnItNorFarAway) {
  // A plateau at 300 m (x < 40), a 60-degree face down to a plain at 100 m sloping gently east.
  Heightfield heights(129, 65, 0.0f, 10.0);
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 129; ++x) {
      const double face = std::clamp(300.0 - (x - 40) * 10.0 * std::sqrt(3.0), 100.0, 300.0);
      heights(x, y) = static_cast<float>(face - 0.3 * x);
    }
  const std::vector<std::uint8_t> texels = ground_map_texels(heights, {});
  const int w = heights.width();
  int foot = 0;
  while (foot < w && heights(foot, 32) > 100.0f - 0.3f * static_cast<float>(foot) + 1.0f) ++foot;
  EXPECT_GT(channel(texels, w, foot + 2, 32, 2), 100) << "at the foot, x = " << foot + 2;
  EXPECT_LT(channel(texels, w, foot + 60, 32, 2), 20) << "600 m out on the plain";
  EXPECT_LT(channel(texels, w, 20, 32, 2), 20) << "on the plateau above";
}

TEST(GroundMaps, DetailNoiseIsTileableAndDeterministic) {
  const DetailNoise a = detail_noise_texels(64, 0.85), b = detail_noise_texels(64, 0.85);
  EXPECT_EQ(a.texels, b.texels);
  EXPECT_GT(a.gradient_scale, 1.0);
  // Slopes of both signs, and the height spread over most of the byte range.
  int low = 255, high = 0, east_min = 255, east_max = 0;
  for (std::size_t i = 0; i < a.texels.size(); i += 4) {
    low = std::min<int>(low, a.texels[i + 2]), high = std::max<int>(high, a.texels[i + 2]);
    east_min = std::min<int>(east_min, a.texels[i]), east_max = std::max<int>(east_max, a.texels[i]);
  }
  EXPECT_LT(low, 64);
  EXPECT_GT(high, 192);
  EXPECT_LT(east_min, 40);
  EXPECT_GT(east_max, 216);
}

TEST(GroundMaps, WorldNoiseMatchesAcrossNeighbouringTiles) {
  // Two tiles of one world, side by side: the shared column has the same noise.
  const auto west = world_noise_texels(65, 65, 10.0, 0.0, 0.0), east = world_noise_texels(65, 65, 10.0, 640.0, 0.0);
  for (int y = 0; y < 65; ++y)
    for (int c = 0; c < 2; ++c)
      EXPECT_NEAR(west[(static_cast<std::size_t>(y) * 65 + 64) * 2 + c], east[(static_cast<std::size_t>(y) * 65) * 2 + c], 1) << y;
}

}  // namespace
}  // namespace sansui::look

#include "look/downsample.hpp"

#include <gtest/gtest.h>

#include "look/surface_maps.hpp"

namespace sansui::look {
namespace {

TEST(Downsample, StepIsTheSmallestThatFits) {
  EXPECT_EQ(downsample_step(1025, 1025, 1025), 1);
  EXPECT_EQ(downsample_step(1025, 1025, 513), 2);
  EXPECT_EQ(downsample_step(16385, 16385, 2049), 8);
  EXPECT_EQ(downsample_step(16385, 16385, 1025), 16);
  EXPECT_EQ(downsample_step(1000, 300, 257), 4);  // 999 / 4 + 1 = 250 <= 257
  EXPECT_EQ(downsample_step(2, 2, 65), 1);
}

TEST(Downsample, KeepsCornersSpacingAndOrigin) {
  Heightfield heights(1025, 513, 0.0f, 10.0);
  heights.origin_x_m = 5000.0;
  heights.origin_y_m = -300.0;
  const Heightfield small = downsample(heights, 4);
  EXPECT_EQ(small.width(), 257);
  EXPECT_EQ(small.height(), 129);
  EXPECT_DOUBLE_EQ(small.cell_size_m, 40.0);
  EXPECT_DOUBLE_EQ(small.origin_x_m, 5000.0);
  EXPECT_DOUBLE_EQ(small.origin_y_m, -300.0);
}

TEST(Downsample, AveragesTheBoxAroundEachSample) {
  Heightfield heights(9, 9, 0.0f);
  heights(4, 4) = 90.0f;                             // one spike
  const Heightfield small = downsample(heights, 2);  // boxes of 3x3 around even samples
  EXPECT_FLOAT_EQ(small(2, 2), 10.0f);
  EXPECT_FLOAT_EQ(small(0, 0), 0.0f);
  // A constant stays constant, edges included.
  const Heightfield constant = downsample(Heightfield(17, 17, 7.5f), 4);
  for (float value : constant.values()) EXPECT_FLOAT_EQ(value, 7.5f);
}

TEST(SurfaceMaps, GradientOfAPlaneIsItsSlope) {
  Heightfield heights(5, 4, 0.0f, 2.0);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 5; ++x) heights(x, y) = static_cast<float>(3.0 * x - 1.0 * y);
  const std::vector<float> texels = height_and_gradient_texels(heights);
  ASSERT_EQ(texels.size(), 5u * 4u * 4u);
  for (int i = 0; i < 20; ++i) {
    EXPECT_FLOAT_EQ(texels[4 * i], heights.data()[i]);
    EXPECT_FLOAT_EQ(texels[4 * i + 1], 1.5f);   // 3 m per 2 m east, edges included
    EXPECT_FLOAT_EQ(texels[4 * i + 2], -0.5f);  // -1 m per 2 m south
  }
}

TEST(SurfaceMaps, NoiseTileIsDeterministicSpreadAndSeamless) {
  const auto noise = tileable_noise_texels(64);
  ASSERT_EQ(noise.size(), 64u * 64u * 2u);
  EXPECT_EQ(noise, tileable_noise_texels(64));
  int low = 255, high = 0;
  for (auto value : noise) {
    low = std::min<int>(low, value);
    high = std::max<int>(high, value);
  }
  EXPECT_LT(low, 60);
  EXPECT_GT(high, 195);
  // Seamless: the jump across the tile's edge is no bigger than between neighbours inside.
  int inside = 0, across = 0;
  for (int y = 0; y < 64; ++y) {
    inside = std::max(inside, std::abs(noise[(y * 64 + 31) * 2] - noise[(y * 64 + 32) * 2]));
    across = std::max(across, std::abs(noise[(y * 64 + 63) * 2] - noise[(y * 64 + 0) * 2]));
  }
  EXPECT_LE(across, std::max(inside, 1) * 2);
}

}  // namespace
}  // namespace sansui::look

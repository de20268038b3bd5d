#include "mesh/preview.hpp"

#include <gtest/gtest.h>

namespace sansui::mesh {
namespace {

TEST(ShadedRelief, SlopesFacingTheNorthWestLightAreBrighter) {
  // A ridge running north-south: the west slope faces the light, the east slope turns away.
  Heightfield ridge(65, 65, 0.0f, 10.0);
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) ridge(x, y) = float(320 - 10 * std::abs(x - 32));
  const Image image = shaded_relief(ridge);
  ASSERT_EQ(image.width(), 65);
  ASSERT_EQ(image.height(), 65);
  const Rgba8 west = image(16, 32), east = image(48, 32);
  EXPECT_GT(int(west.r) + west.g + west.b, int(east.r) + east.g + east.b + 100);
  EXPECT_EQ(west.a, 255);
}

}  // namespace
}  // namespace sansui::mesh

#include "water/surface_water.hpp"

#include <cstdint>

#include <gtest/gtest.h>

#include "test_util.hpp"
#include "water/water_test_util.hpp"

namespace sansui::water {
namespace {

template <class T>
std::uint64_t hash_of(const Grid<T>& grid) {
  return ::sansui::test::fnv1a(grid.values().data(), grid.values().size() * sizeof(T));
}

// Wetness is the index scaled between its 70th and 99th percentiles over land: 70 % of the land
// reads 0, and at least 1 % of it 1 (the wettest percent, and the water).
TEST(SurfaceWater, WetnessSpansTheSeventiethToTheNinetyNinthPercentileOfTheLand) {
  const Heightfield ground = test::midpoint_terrain(257, 30.0, 5);
  FlowParams params;
  params.sea_level_m = 0.0;
  const SurfaceWater water = surface_water(ground, params);
  std::size_t land = 0, dry = 0, wet = 0;
  for (std::size_t i = 0; i < ground.size(); ++i) {
    if (ground.values()[i] < 0.0f) continue;
    ++land;
    dry += water.wetness.values()[i] == 0.0f ? 1 : 0;
    wet += water.wetness.values()[i] == 1.0f ? 1 : 0;
  }
  ASSERT_GT(land, 10000u);
  EXPECT_NEAR(static_cast<double>(dry) / static_cast<double>(land), 0.70, 0.01);
  EXPECT_GE(static_cast<double>(wet) / static_cast<double>(land), 0.01);
}

// The bytes of every layer, pinned: a change to them is a change of the outputs' bytes, which
// CHANGELOG.md must announce.
TEST(SurfaceWater, BytesAreTheSameAsEver) {
  const Heightfield ground = test::midpoint_terrain(257, 30.0, 5);
  FlowParams params;
  params.sea_level_m = 0.0;
  const SurfaceWater water = surface_water(ground, params);
  EXPECT_EQ(hash_of(water.surface), 7908218788393538689u);
  EXPECT_EQ(hash_of(water.depth_m), 970887094334153279u);
  EXPECT_EQ(hash_of(water.wetness), 3285924057007383909u);
  EXPECT_EQ(hash_of(water.area_m2), 3612735586040962534u);
  EXPECT_EQ(water.rivers.rivers.size(), 7u);
  EXPECT_EQ(hash_of(water.rivers.channel), 7026560361452376825u);
  EXPECT_EQ(water.lakes.lakes.size(), 31u);
}

}  // namespace
}  // namespace sansui::water

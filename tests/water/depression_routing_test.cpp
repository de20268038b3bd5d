#include "water/depression_routing.hpp"

#include <cstdlib>

#include <gtest/gtest.h>

#include "water/water_test_util.hpp"

namespace sansui::water {
namespace {

/// True if `to` is one of the eight neighbours of `from` in a grid of the given width.
bool neighbours(CellIndex from, CellIndex to, int width) {
  const int dx = to % width - from % width, dy = to / width - from / width;
  return from != to && std::abs(dx) <= 1 && std::abs(dy) <= 1;
}

TEST(DepressionRouting, EveryCellReachesAnOutletThroughNeighbours) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const Heightfield ground =
        test::random_heights(5 + static_cast<int>(seed % 23), 4 + static_cast<int>(seed % 17), seed, seed % 2 ? 4 : 1000);
    Outlets outlets;
    if (seed % 3 == 0) outlets.sea_level_m = 1.5;
    const DepressionRouting routing = route_depressions(ground, outlets);
    const int w = ground.width();
    for (int y = 0; y < ground.height(); ++y)
      for (int x = 0; x < w; ++x) {
        auto c = static_cast<CellIndex>(y * w + x);
        std::size_t steps = 0;
        // Downstream of any cell lies an outlet, within as many steps as there are cells.
        while (routing.receiver.data()[c] != c) {
          ASSERT_TRUE(neighbours(c, routing.receiver.data()[c], w)) << "seed " << seed;
          c = routing.receiver.data()[c];
          ASSERT_LE(++steps, ground.size()) << "seed " << seed << ": a cycle";
        }
        ASSERT_TRUE(is_outlet(ground, outlets, c % w, c / w)) << "seed " << seed << ": cell " << c << " is a pit";
      }
    // The levels themselves are checked against a brute-force fill in priority_flood_test.cpp.
  }
}

TEST(DepressionRouting, RoughFractalTerrainDrainsWithSameBytesWithOneAndTwoThreads) {
  const Heightfield ground = test::midpoint_terrain(257, 10.0, 4);
  test::expect_same_bytes_with_one_and_two_threads([&] {
    const DepressionRouting routing = route_depressions(ground, {0.0});
    EXPECT_GT(routing.depressions, 100);  // the finest octave leaves many small pits
    return test::hash_of(routing.receiver) ^ test::hash_of(routing.water_level);
  });
}

}  // namespace
}  // namespace sansui::water

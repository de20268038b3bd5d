#include "water/priority_flood.hpp"

#include <algorithm>
#include <limits>

#include <gtest/gtest.h>

#include "water/flow.hpp"
#include "water/neighbours.hpp"
#include "water/water_test_util.hpp"

namespace sansui::water {
namespace {

/// The minimal depression fill by its definition: the level of a cell is the lowest, over all
/// paths to an outlet, of the highest ground on the path. Iterated to a fixed point
/// (Planchon & Darboux 2001 without epsilon): slow, obviously right.
Heightfield brute_force_fill(const Heightfield& ground, const Outlets& outlets) {
  const int w = ground.width(), h = ground.height();
  Heightfield level(w, h, std::numeric_limits<float>::infinity());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (is_outlet(ground, outlets, x, y)) level(x, y) = ground(x, y);
  for (bool changed = true; changed;) {
    changed = false;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (is_outlet(ground, outlets, x, y)) continue;
        float lowest = std::numeric_limits<float>::infinity();
        for (std::size_t k = 0; k < 8; ++k) lowest = std::min(lowest, level(x + neighbour_dx[k], y + neighbour_dy[k]));
        const float candidate = std::max(ground(x, y), lowest);
        if (candidate < level(x, y)) level(x, y) = candidate, changed = true;
      }
  }
  return level;
}

TEST(PriorityFlood, LakesFillEqualsBruteForceOnRandomGrids) {
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const int w = 3 + static_cast<int>(seed % 11), h = 3 + static_cast<int>((seed * 7) % 13);
    const Heightfield ground = test::random_heights(w, h, seed, seed % 2 ? 5 : 1000);
    Outlets outlets;
    if (seed % 3 == 0) outlets.sea_level_m = 1.5;
    const LakeFill fill = fill_depressions_with_lakes(ground, outlets);
    const Heightfield expected = brute_force_fill(ground, outlets);
    for (std::size_t i = 0; i < ground.size(); ++i)
      ASSERT_EQ(fill.surface.data()[i], expected.data()[i]) << "seed " << seed << " cell " << i;
  }
}

TEST(PriorityFlood, LakesAreLabelledFloodedCellsWithOneLevel) {
  const Heightfield ground = test::random_heights(40, 30, 5, 20);
  const LakeFill fill = fill_depressions_with_lakes(ground, {});
  ASSERT_FALSE(fill.lakes.empty());
  std::vector<std::int64_t> cells(fill.lakes.size(), 0);
  for (std::size_t i = 0; i < ground.size(); ++i) {
    const std::int32_t label = fill.lake.data()[i];
    EXPECT_EQ(label != 0, fill.surface.data()[i] > ground.data()[i]);
    if (label == 0) continue;
    const Lake& lake = fill.lakes[static_cast<std::size_t>(label - 1)];
    EXPECT_EQ(fill.surface.data()[i], lake.level_m);
    ++cells[static_cast<std::size_t>(label - 1)];
  }
  for (std::size_t k = 0; k < fill.lakes.size(); ++k) {
    EXPECT_EQ(cells[k], fill.lakes[k].cells);
    EXPECT_GT(fill.lakes[k].volume_m3, 0.0);
  }
}

TEST(PriorityFlood, EpsilonFillDrainsEveryCellToAnOutlet) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Heightfield ground = test::random_heights(37, 29, seed, seed % 2 ? 3 : 500);
    Outlets outlets;
    if (seed % 4 == 0) outlets.sea_level_m = 1.0;
    const Heightfield surface = fill_depressions_epsilon(ground, outlets);
    const LakeFill lakes = fill_depressions_with_lakes(ground, outlets);
    for (std::size_t i = 0; i < ground.size(); ++i) {
      ASSERT_GE(surface.data()[i], lakes.surface.data()[i]);
      ASSERT_LE(surface.data()[i], lakes.surface.data()[i] + 1e-3f);  // a few float steps per flat cell
    }
    // Every cell that is not an outlet has a strictly lower neighbour, so following D8 ends at an outlet.
    const Grid<CellIndex> receiver = d8_receivers(surface, outlets);
    for (int y = 0; y < ground.height(); ++y)
      for (int x = 0; x < ground.width(); ++x) {
        CellIndex c = y * ground.width() + x;
        for (int hops = 0; receiver.data()[c] != c; ++hops) {
          ASSERT_LT(surface.data()[receiver.data()[c]], surface.data()[c]);
          ASSERT_LT(hops, static_cast<int>(ground.size()));
          c = receiver.data()[c];
        }
        EXPECT_TRUE(is_outlet(surface, outlets, c % ground.width(), c / ground.width())) << "seed " << seed << " pit at " << c;
      }
  }
}

TEST(PriorityFlood, OutletsKeepTheirHeightsAndNothingIsLowered) {
  const Heightfield ground = test::random_heights(20, 20, 9, 50);
  const Outlets outlets{20.0};
  const Heightfield surface = fill_depressions_epsilon(ground, outlets);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) {
      EXPECT_GE(surface(x, y), ground(x, y));
      if (is_outlet(ground, outlets, x, y)) {
        EXPECT_EQ(surface(x, y), ground(x, y));
      }
    }
}

TEST(PriorityFlood, RejectsNonFiniteHeights) {
  Heightfield ground(5, 5, 1.0f);
  ground(2, 2) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(fill_depressions_epsilon(ground, {}), InputError);
}

}  // namespace
}  // namespace sansui::water

// Seamless tiles and previews: any window of the world, at any level of detail, equals that
// window of the whole world bit for bit.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "terrain/midpoint.hpp"

namespace sansui::terrain {
namespace {

bool same_bytes(ConstGridView<float> a, ConstGridView<float> b) {
  if (a.width != b.width || a.height != b.height) return false;
  for (int y = 0; y < a.height; ++y)
    if (std::memcmp(a.row(y).data(), b.row(y).data(), a.row(y).size_bytes()) != 0) return false;
  return true;
}

class WorldTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    MidpointParams params;
    params.seed = 31337;
    params.hurst = 0.7;
    world_ = new Heightfield(generate_midpoint(params, 4097));
  }
  static void TearDownTestSuite() { delete world_; }
  static MidpointParams params() {
    MidpointParams p;
    p.seed = 31337;
    p.hurst = 0.7;
    return p;
  }
  static Heightfield* world_;
};
Heightfield* WorldTest::world_ = nullptr;

TEST_F(WorldTest, FourByFourTilesInShuffledOrderEqualTheWholeWorld) {
  constexpr int tile = 1025;  // tiles share their border samples
  std::vector<int> order(16);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937(5));  // test-only order, not terrain randomness
  for (int index : order) {
    const int tx = index % 4, ty = index / 4;
    const Rect window{tx * (tile - 1), ty * (tile - 1), tx * (tile - 1) + tile, ty * (tile - 1) + tile};
    const Heightfield piece = generate_midpoint(params(), WorldWindow{12, 0, window});
    EXPECT_TRUE(same_bytes(piece.view(), world_->view(window))) << "tile " << tx << "," << ty;
  }
}

TEST_F(WorldTest, OddWindowsEqualTheWholeWorld) {
  for (Rect window : {Rect{1, 1, 2, 2}, Rect{4095, 0, 4097, 4097}, Rect{777, 1234, 1300, 1301}, Rect{0, 3000, 4097, 3003}}) {
    const Heightfield piece = generate_midpoint(params(), WorldWindow{12, 0, window});
    EXPECT_TRUE(same_bytes(piece.view(), world_->view(window)));
  }
}

TEST_F(WorldTest, LevelOfDetailThreeIsEveryEighthSample) {
  const Heightfield preview = generate_midpoint(params(), WorldWindow{12, 3, Rect{0, 0, 513, 513}});
  ASSERT_EQ(preview.width(), 513);
  for (int y = 0; y < 513; ++y)
    for (int x = 0; x < 513; ++x)
      ASSERT_EQ(std::bit_cast<std::uint32_t>(preview(x, y)), std::bit_cast<std::uint32_t>((*world_)(8 * x, 8 * y))) << x << "," << y;
}

TEST_F(WorldTest, TileOfAPreviewIsThePreviewOfTheTile) {
  const Rect window{64, 128, 64 + 129, 128 + 129};
  const Heightfield piece = generate_midpoint(params(), WorldWindow{12, 2, window});
  for (int y = 0; y < window.height(); ++y)
    for (int x = 0; x < window.width(); ++x) ASSERT_EQ(piece(x, y), (*world_)(4 * (window.x0 + x), 4 * (window.y0 + y)));
}

}  // namespace
}  // namespace sansui::terrain

namespace sansui::terrain {
namespace {

// Refining from a given coarse world (an eroded one, say): tiles join bit for bit, windows equal
// the whole refined world, and the coarse points keep the given values.
TEST(RefineMidpoint, TilesOfAChangedCoarseWorldJoinAndKeepItsValues) {
  MidpointParams params;
  params.seed = 7;
  const int world_levels = 9, coarse_lod = 2;  // a 513 world refined from its 129 version
  const int coarse_side = (1 << (world_levels - coarse_lod)) + 1;
  Heightfield coarse = generate_midpoint(params, WorldWindow{world_levels, coarse_lod, Rect{0, 0, coarse_side, coarse_side}});
  for (int y = 0; y < coarse_side; ++y)  // a change no refinement would make: a straight trench
    for (int x = 40; x < 44; ++x) coarse(x, y) -= 300.0f;

  const int side = (1 << world_levels) + 1;
  const Heightfield whole = refine_midpoint(params, WorldWindow{world_levels, 0, Rect{0, 0, side, side}}, coarse);
  for (int y = 0; y < coarse_side; y += 8)
    for (int x = 0; x < coarse_side; x += 4) ASSERT_NEAR(whole(x * 4, y * 4), coarse(x, y), 1e-3f) << x << "," << y;

  // 2 x 2 tiles of 257 samples sharing their borders, in any order, equal the whole world.
  for (int ty : {1, 0})
    for (int tx : {0, 1}) {
      const Rect tile{tx * 256, ty * 256, tx * 256 + 257, ty * 256 + 257};
      const Heightfield part = refine_midpoint(params, WorldWindow{world_levels, 0, tile}, coarse);
      ASSERT_TRUE(same_bytes(part.view(), whole.view(tile))) << "tile " << tx << "," << ty;
    }

  // Refined from the unchanged coarse world, the result is the plain world up to float rounding.
  const Heightfield plain = generate_midpoint(params, side);
  const Heightfield again =
      refine_midpoint(params, WorldWindow{world_levels, 0, Rect{0, 0, side, side}},
                      generate_midpoint(params, WorldWindow{world_levels, coarse_lod, Rect{0, 0, coarse_side, coarse_side}}));
  float worst = 0.0f;
  for (std::size_t i = 0; i < plain.size(); ++i) worst = std::max(worst, std::abs(plain.values()[i] - again.values()[i]));
  EXPECT_LT(worst, 1e-3f);
}

TEST(RefineMidpoint, RejectsACoarseWorldOfTheWrongShape) {
  MidpointParams params;
  EXPECT_THROW(refine_midpoint(params, WorldWindow{9, 0, Rect{0, 0, 513, 513}}, Heightfield(100, 100, 0.0f)), InputError);
  EXPECT_THROW(refine_midpoint(params, WorldWindow{9, 4, Rect{0, 0, 33, 33}}, Heightfield(129, 129, 0.0f)), InputError);
}

}  // namespace
}  // namespace sansui::terrain

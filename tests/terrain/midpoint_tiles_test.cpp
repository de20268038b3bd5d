// Seamless tiles and previews: any window of the world, at any level of detail, equals that
// window of the whole world bit for bit.
#include <algorithm>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

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

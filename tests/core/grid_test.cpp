#include "core/grid.hpp"

#include <gtest/gtest.h>

namespace sansui {
namespace {

TEST(Grid, IsRowMajorWithXInner) {
  Grid<int> grid(3, 2, 0);
  grid(2, 1) = 7;
  EXPECT_EQ(grid.data()[1 * 3 + 2], 7);
  EXPECT_EQ(grid.size(), 6u);
}

TEST(Grid, ViewsOfSubRectanglesShareStorage) {
  Grid<int> grid(4, 4, 0);
  GridView<int> view = grid.view(Rect{1, 2, 3, 4});
  EXPECT_EQ(view.width, 2);
  EXPECT_EQ(view.height, 2);
  view(1, 0) = 5;
  EXPECT_EQ(grid(2, 2), 5);
  EXPECT_EQ(view.sub(Rect{1, 1, 2, 2})(0, 0), grid(2, 3));
}

TEST(Grid, CopyIsDeepAndKeepsMetadata) {
  Grid<float> grid(2, 2, 1.0f, 30.0);
  grid.origin_x_m = 5.0;
  Grid<float> copy = grid;
  copy(0, 0) = 2.0f;
  EXPECT_EQ(grid(0, 0), 1.0f);
  EXPECT_EQ(copy.cell_size_m, 30.0);
  EXPECT_EQ(copy.origin_x_m, 5.0);
}

TEST(Grid, CopyOfAViewIsThatRectangle) {
  Grid<int> grid(4, 3, 0);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) grid(x, y) = 10 * y + x;
  const Grid<int> part = copy_of(grid.view(Rect{1, 1, 3, 3}));
  EXPECT_EQ(part.width(), 2);
  EXPECT_EQ(part(0, 0), 11);
  EXPECT_EQ(part(1, 1), 22);
}

}  // namespace
}  // namespace sansui

#include "contour/extract.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "contour/grid_frame.hpp"
#include "core/error.hpp"

namespace sansui::contour {
namespace {

/// A cone of height 100 m and radius 50 m (minus a pit) on a 101 x 101 grid of 1 m cells,
/// centred at east 0, north 0.
Heightfield cone_with_pit() {
  Heightfield h(101, 101, 0.0f, 1.0);
  h.origin_x_m = -50.0;
  h.origin_y_m = -50.0;
  const GridFrame frame = GridFrame::of(h);
  for (int j = 0; j < 101; ++j)
    for (int i = 0; i < 101; ++i) {
      const Point p = frame.at(i, j);
      double z = std::max(0.0, 100.0 - 2.0 * length(p));
      const double pit = length(p - Point{12, 0});
      if (pit < 6.0) z -= 30.0 * (1.0 - pit / 6.0);
      h(i, j) = static_cast<float>(z);
    }
  return h;
}

TEST(Extract, ConeGivesACircleAroundHigherGround) {
  const Heightfield h = cone_with_pit();
  const auto rings = extract_contours(h, 30.0);  // radius 35
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_GT(signed_area(rings[0]), 0.0);
  for (const Point& p : rings[0]) EXPECT_NEAR(length(p), 35.0, 0.1);
  EXPECT_NEAR(signed_area(rings[0]), 3.14159265 * 35.0 * 35.0, 0.01 * 3.14159265 * 35.0 * 35.0);
}

TEST(Extract, PitsAreClockwise) {
  const Heightfield h = cone_with_pit();
  // At 55 m the pit (its bottom at 76 - 30 = 46 m) is a closed depression inside the 55 m contour.
  const auto rings = extract_contours(h, 55.0);
  int hills = 0, pits = 0;
  for (const Ring& r : rings) (signed_area(r) > 0 ? hills : pits)++;
  EXPECT_EQ(hills, 1);
  EXPECT_EQ(pits, 1);
}

TEST(Extract, ContoursAtTheBorderCloseHalfACellOutside) {
  Heightfield flat(10, 10, 5.0f, 2.0);
  const auto rings = extract_contours(flat, 1.0);
  ASSERT_EQ(rings.size(), 1u);
  // 9 cells of 2 m plus half a cell on each side, less the four corners cut diagonally.
  EXPECT_NEAR(signed_area(rings[0]), 20.0 * 20.0 - 4 * 0.5, 1e-9);
}

TEST(Extract, SamplesEqualToTheLevelDoNotBreakRings) {
  // Integer DEMs at integer levels: many samples lie exactly on the level.
  Heightfield h(30, 30, 0.0f);
  for (int j = 0; j < 30; ++j)
    for (int i = 0; i < 30; ++i) h(i, j) = static_cast<float>(std::min({i, j, 29 - i, 29 - j}) % 4);
  for (double level : {0.0, 1.0, 2.0}) {
    for (const Ring& r : extract_contours(h, level)) {
      EXPECT_GE(r.size(), 3u);
      EXPECT_NE(signed_area(r), 0.0);
    }
  }
}

TEST(Extract, PickChoosesTheLargestOrTheOneAroundAPoint) {
  Heightfield h(60, 30, 0.0f);
  for (int j = 5; j < 25; ++j) {
    for (int i = 5; i < 25; ++i) h(i, j) = 10.0f;   // a big block
    for (int i = 40; i < 50; ++i) h(i, j) = 10.0f;  // a small one
  }
  const Ring largest = pick_contour(h, 5.0, std::nullopt);
  EXPECT_NEAR(signed_area(largest), 20.0 * 20.0, 1.0);
  const Ring small = pick_contour(h, 5.0, Point{45.0, -15.0});
  EXPECT_NEAR(signed_area(small), 10.0 * 20.0, 1.0);
}

void expect_error(const std::function<void()>& f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "no error; expected one mentioning " << fragment;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(Extract, BadLevelOrPickIsRejected) {
  const Heightfield h = cone_with_pit();
  expect_error([&] { pick_contour(h, 150.0, std::nullopt); }, "--level 150 is outside the DEM's range");
  expect_error([&] { pick_contour(h, -1.0, std::nullopt); }, "--level -1 is outside");
  expect_error([&] { pick_contour(h, 50.0, Point{45.0, 45.0}); }, "--pick 45,45 lies outside every contour at level 50");
}

}  // namespace
}  // namespace sansui::contour

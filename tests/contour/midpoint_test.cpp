#include "contour/midpoint.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "contour/decimate.hpp"
#include "tests/contour/contour_test_util.hpp"

namespace sansui::contour {
namespace {

TEST(MidpointDisplacement, SplitsUntilNoSegmentExceedsTwiceD0) {
  const Ring ring{{0, 0}, {100, 0}, {100, 7}, {0, 7}};
  const MidpointDisplacementParams params{10.0, 2.0, 0.0, 20.0};
  const Ring out = displace_midpoints(ring, params, 1, 2);
  for (std::size_t i = 0; i < out.size(); ++i) EXPECT_LE(distance(out[i], out[(i + 1) % out.size()]), 10.0 + 1e-9);
  EXPECT_GT(out.size(), 20u);
  // The original vertices stay, in order.
  std::size_t found = 0;
  for (const Point& p : out)
    if (found < ring.size() && p == ring[found]) ++found;
  EXPECT_EQ(found, ring.size());
}

TEST(MidpointDisplacement, OneSplitMovesTheMidpointPerpendicularlyByMinOfDAndLTanTheta) {
  // Segment of length 2l = 15 with 2 d0 = 10: exactly one split (halves of 7.5).
  const double l = 7.5;
  for (std::uint64_t key = 1; key <= 40; ++key) {
    const Ring ring{{0, 0}, {15, 0}, {15, 1}, {0, 1}};
    const MidpointDisplacementParams params{10.0, 1.2, 5.0, 15.0};
    const Ring out = displace_midpoints(ring, params, key, key + 1000);
    ASSERT_EQ(out.size(), 6u);  // one new point on each long side
    const Point m = out[1];
    EXPECT_DOUBLE_EQ(m.x, 7.5);  // perpendicular: along the normal only
    const double shift = std::fabs(m.y);
    const double low = std::min(1.2, l * std::tan(5.0 * std::numbers::pi / 180.0));
    EXPECT_GE(shift, low - 1e-12);
    EXPECT_LE(shift, 1.2 + 1e-12);
  }
}

TEST(MidpointDisplacement, BothSidesOccur) {
  int up = 0, down = 0;
  for (std::uint64_t key = 1; key <= 64; ++key) {
    const Ring out = displace_midpoints({{0, 0}, {15, 0}, {15, 1}, {0, 1}}, {10.0, 1.0, 10.0, 20.0}, key, 7);
    (out[1].y > 0 ? up : down)++;
  }
  EXPECT_GT(up, 16);
  EXPECT_GT(down, 16);
}

TEST(Decimate, DropsCollinearPointsFirstAndReachesTheLongFraction) {
  // A 100 m square sampled every metre: only corners matter.
  Ring ring;
  for (int i = 0; i < 100; ++i) ring.push_back({static_cast<double>(i), 0});
  for (int i = 0; i < 100; ++i) ring.push_back({100, static_cast<double>(i)});
  for (int i = 0; i < 100; ++i) ring.push_back({100.0 - i, 100});
  for (int i = 0; i < 100; ++i) ring.push_back({0, 100.0 - i});
  const Ring out = drop_collinear_points(ring, {20.0, 0.2, 4});
  int long_segments = 0;
  for (std::size_t i = 0; i < out.size(); ++i) long_segments += distance(out[i], out[(i + 1) % out.size()]) > 20.0 ? 1 : 0;
  EXPECT_GE(long_segments, 0.2 * static_cast<double>(out.size()));
  EXPECT_LT(out.size(), ring.size() / 4);
  EXPECT_NEAR(signed_area(out), 10000.0, 1e-9);  // corners were never removed
}

TEST(Decimate, KeepsAtLeastMinVertices) {
  const Ring ring = test::circle({0, 0}, 10.0, 100);
  EXPECT_EQ(drop_collinear_points(ring, {1000.0, 0.5, 8}).size(), 8u);
}

}  // namespace
}  // namespace sansui::contour

#include "contour/loop_removal.hpp"

#include <gtest/gtest.h>

#include "contour/crossings.hpp"
#include "contour/midpoint.hpp"
#include "core/random.hpp"
#include "tests/contour/contour_test_util.hpp"

namespace sansui::contour {
namespace {

/// A 100 m square whose bottom edge twists into a small clockwise loop below it (outward).
Ring outward_twist() {
  return {{0, 0}, {40, 0}, {60, 0}, {60, -10}, {50, -10}, {50, 5}, {100, 5}, {100, 100}, {0, 100}};
}
/// The same with the loop above the edge (inside, counter-clockwise: winding number 2).
Ring inward_twist() {
  return {{0, 0}, {40, 0}, {60, 0}, {60, 10}, {50, 10}, {50, -5}, {100, -5}, {100, 100}, {0, 100}};
}
/// Fig. 18's pattern: a loop inside a loop (…-4-5-…-5-…-4-…).
Ring nested_twist() {
  return {{0, 0},    {40, 0},   {70, 0}, {70, -20}, {60, -20},  {60, -5}, {66, -5},
          {66, -12}, {55, -12}, {55, 5}, {100, 5},  {100, 100}, {0, 100}};
}

void expect_simple_ccw(const std::vector<Ring>& rings, double area, const std::string& what) {
  ASSERT_EQ(rings.size(), 1u) << what;
  EXPECT_TRUE(self_crossings(rings[0]).empty()) << what << ": " << test::describe(rings[0]);
  EXPECT_NEAR(signed_area(rings[0]), area, 1e-3) << what;
}

TEST(LoopRemoval, BothMethodsCutAnOutwardTwist) {
  ASSERT_EQ(self_crossings(outward_twist()).size(), 1u);
  expect_simple_ccw(remove_loops(outward_twist(), {1, 5}), 9750.0, "method 1");
  expect_simple_ccw(remove_loops(outward_twist(), {2, 5}), 9750.0, "method 2");
  const Ring walked = remove_loops_by_walk(outward_twist(), 5);
  EXPECT_TRUE(test::same_ring(walked, {{0, 0}, {40, 0}, {50, 0}, {50, 5}, {100, 5}, {100, 100}, {0, 100}}, 1e-9));
}

TEST(LoopRemoval, BothMethodsCutAnInwardTwist) {
  expect_simple_ccw(remove_loops(inward_twist(), {1, 5}), 10250.0, "method 1");
  expect_simple_ccw(remove_loops(inward_twist(), {2, 5}), 10250.0, "method 2");
}

TEST(LoopRemoval, NestedLoopsAsInFigure18) {
  EXPECT_EQ(self_crossings(nested_twist()).size(), 2u);
  // Without the excursion the square's bottom is y = 0 up to x = 55, then y = 5.
  const double area = 55.0 * 100.0 + 45.0 * 95.0;
  expect_simple_ccw(remove_loops(nested_twist(), {1, 5}), area, "method 1");
  expect_simple_ccw(remove_loops(nested_twist(), {2, 5}), area, "method 2");
}

TEST(LoopRemoval, SmallFacesGoAndLargeOnesStayWithMethod1) {
  // Threshold above the loop's 4 segments and below the main face's 7.
  const auto rings = remove_loops_by_faces(inward_twist(), 6);
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_NEAR(signed_area(rings[0]), 10250.0, 1e-3);
}

TEST(LoopRemoval, SimpleCurvesComeBackUnchanged) {
  const Ring ring = test::circle({3, 4}, 50.0, 40);
  for (int method : {1, 2}) {
    const auto rings = remove_loops(ring, {method, 16});
    ASSERT_EQ(rings.size(), 1u);
    EXPECT_EQ(rings[0], ring);
  }
}

TEST(LoopRemoval, StronglyDisplacedCurvesBecomeSimple) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    // Large displacements (d'' = 3 x the segment length) tangle the curve.
    const Ring tangled = displace_midpoints(test::circle({0, 0}, 100.0, 24), {4.0, 12.0, 30.0, 80.0}, seed, seed + 99);
    for (int method : {1, 2}) {
      const auto rings = remove_loops(tangled, {method, 16});
      ASSERT_FALSE(rings.empty()) << "seed " << seed << " method " << method;
      for (const Ring& r : rings) {
        EXPECT_TRUE(self_crossings(r).empty()) << "seed " << seed << " method " << method;
        EXPECT_GT(signed_area(r), 0.0) << "seed " << seed << " method " << method;
      }
    }
  }
}

TEST(Crossings, BowTieHasOneCrossingInTheMiddle) {
  const auto c = self_crossings({{0, 0}, {10, 10}, {10, 0}, {0, 10}});
  ASSERT_EQ(c.size(), 1u);
  EXPECT_NEAR(c[0].at.x, 5.0, 1e-12);
  EXPECT_NEAR(c[0].at.y, 5.0, 1e-12);
}

TEST(Crossings, GridSearchFindsWhatBruteForceFinds) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Ring ring;
    const std::uint64_t key = rng::stream_key(seed, 5);
    for (int i = 0; i < 150; ++i)
      ring.push_back({100.0 * rng::to_uniform(rng::bits(key, rng::pack(i, 0))), 100.0 * rng::to_uniform(rng::bits(key, rng::pack(i, 1)))});
    std::size_t brute = 0;
    const std::size_t n = ring.size();
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 2; b < n; ++b) {
        if (a == 0 && b == n - 1) continue;
        const Point p = ring[a], r = ring[a + 1] - p, q = ring[b], s = ring[(b + 1) % n] - q;
        const double den = cross(r, s);
        if (den == 0.0) continue;
        const double t = cross(q - p, s) / den, u = cross(q - p, r) / den;
        brute += (t >= 0 && t < 1 && u >= 0 && u < 1) ? 1 : 0;
      }
    EXPECT_EQ(self_crossings(ring).size(), brute) << "seed " << seed;
  }
}

TEST(Crossings, BetweenTwoOverlappingSquares) {
  Ring moved = test::square(10);
  for (Point& p : moved) p = p + Point{5, 5};
  EXPECT_EQ(crossings_between(test::square(10), moved).size(), 2u);
  Ring far = test::square(10);
  for (Point& p : far) p = p + Point{50, 0};
  EXPECT_TRUE(crossings_between(test::square(10), far).empty());
}

}  // namespace
}  // namespace sansui::contour

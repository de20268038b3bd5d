#include "contour/shrink.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "contour/clipping.hpp"
#include "tests/contour/contour_test_util.hpp"

namespace sansui::contour {
namespace {

using test::same_ring;
constexpr double tolerance = 2e-3;  // Clipper works on a 1 mm lattice

std::vector<Ring> shrink(const Ring& ring, double d, Join join, double c = 1.4, bool outward = false) {
  OffsetParams params;
  params.distance_m = d;
  params.join = join;
  params.clip_factor = c;
  params.outward = outward;
  return offset_ring(ring, params);
}

Point polar(Point centre, double radius, double degrees) {
  const double a = degrees * std::numbers::pi / 180.0;
  return {centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)};
}

TEST(Shrink, SquareShrinksToTheSameSquareWithEveryJoin) {
  // A convex polygon has no gaps when shrinking: the join never matters.
  for (Join join : {Join::extended, Join::straight, Join::arc, Join::clipped}) {
    const auto rings = shrink(test::square(10), 1.0, join);
    ASSERT_EQ(rings.size(), 1u) << name_of(join);
    EXPECT_TRUE(same_ring(rings[0], {{1, 1}, {9, 1}, {9, 9}, {1, 9}}, tolerance)) << name_of(join);
  }
}

TEST(Shrink, SquareExpandsWithEachJoin) {
  const Ring square = test::square(10);
  auto one = [&](Join join, double c = 1.4) {
    const auto rings = shrink(square, 1.0, join, c, true);
    EXPECT_EQ(rings.size(), 1u);
    return rings.empty() ? Ring{} : rings[0];
  };
  EXPECT_TRUE(same_ring(one(Join::extended), {{-1, -1}, {11, -1}, {11, 11}, {-1, 11}}, tolerance));
  EXPECT_TRUE(same_ring(one(Join::straight), {{0, -1}, {10, -1}, {11, 0}, {11, 10}, {10, 11}, {0, 11}, {-1, 10}, {-1, 0}}, tolerance));
  // Clipped, c = 1.4: the bisector point at 1.4 (< miter sqrt 2) from each corner.
  const double s = 1.4 / std::sqrt(2.0);
  EXPECT_TRUE(same_ring(
      one(Join::clipped),
      {{0, -1}, {10, -1}, {10 + s, -s}, {11, 0}, {11, 10}, {10 + s, 10 + s}, {10, 11}, {0, 11}, {-s, 10 + s}, {-1, 10}, {-1, 0}, {-s, -s}},
      tolerance));
  // Clipped with c = 3 > sqrt 2 reaches the miter: the extended join.
  EXPECT_TRUE(same_ring(one(Join::clipped, 3.0), {{-1, -1}, {11, -1}, {11, 11}, {-1, 11}}, tolerance));
  // Arc: quarter circles of radius 1 in 15-degree steps around each corner.
  Ring arc;
  const Point corners[4] = {{10, 0}, {10, 10}, {0, 10}, {0, 0}};
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k <= 6; ++k) arc.push_back(polar(corners[c], 1.0, -90.0 + 90.0 * c + 15.0 * k));
  EXPECT_TRUE(same_ring(one(Join::arc), arc, tolerance));
}

TEST(Shrink, LShapeJoinsAtItsReflexCorner) {
  const Ring l_shape{{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}};
  auto one = [&](Join join) {
    const auto rings = shrink(l_shape, 1.0, join);
    EXPECT_EQ(rings.size(), 1u) << name_of(join);
    return rings.empty() ? Ring{} : rings[0];
  };
  EXPECT_TRUE(same_ring(one(Join::extended), {{1, 1}, {5, 1}, {5, 2}, {2, 2}, {2, 5}, {1, 5}}, tolerance));
  EXPECT_TRUE(same_ring(one(Join::straight), {{1, 1}, {5, 1}, {5, 2}, {3, 2}, {2, 3}, {2, 5}, {1, 5}}, tolerance));
  const double s = 1.4 / std::sqrt(2.0);  // c d = 1.4 < miter distance sqrt 2
  EXPECT_TRUE(same_ring(one(Join::clipped), {{1, 1}, {5, 1}, {5, 2}, {3, 2}, {3 - s, 3 - s}, {2, 3}, {2, 5}, {1, 5}}, tolerance));
  Ring arc{{1, 1}, {5, 1}, {5, 2}};
  for (int k = 0; k <= 6; ++k) arc.push_back(polar({3, 3}, 1.0, -90.0 - 15.0 * k));  // (3,2) ... (2,3)
  arc.push_back({2, 5});
  arc.push_back({1, 5});
  EXPECT_TRUE(same_ring(one(Join::arc), arc, tolerance));
}

/// The intersection of the lines p + t u and q + s w.
Point meet(Point p, Point u, Point q, Point w) {
  const double t = cross(q - p, w) / cross(u, w);
  return p + t * u;
}

TEST(Shrink, StarJoinsAtItsFiveInnerCorners) {
  // A five-pointed star, outer radius 10, inner 5. Shrinking by d: the tips become the meeting
  // points of neighbouring offset lines; the inner (reflex) corners get the joins.
  Ring star;
  for (int k = 0; k < 10; ++k) star.push_back(polar({0, 0}, k % 2 == 0 ? 10.0 : 5.0, 90.0 + 36.0 * k));
  const double d = 0.5;
  const std::size_t n = star.size();
  auto direction = [&](std::size_t i) {
    const Point v = star[(i + 1) % n] - star[i];
    return (1.0 / length(v)) * v;
  };
  for (Join join : {Join::extended, Join::straight, Join::arc, Join::clipped}) {
    Ring expected;
    for (std::size_t i = 0; i < n; ++i) {
      const Point u1 = direction((i + n - 1) % n), u2 = direction(i);
      const Point n1 = left_normal(u1), n2 = left_normal(u2);
      const Point a = star[i] + d * n1, b = star[i] + d * n2;
      const Point miter = meet(a, u1, b, u2);
      const bool reflex = cross(u1, u2) < 0.0;
      if (!reflex || join == Join::extended) {
        expected.push_back(miter);
      } else if (join == Join::straight) {
        expected.push_back(a), expected.push_back(b);
      } else if (join == Join::clipped) {
        const double miter_distance = distance(star[i], miter);
        const Point bisector = (1.0 / length(n1 + n2)) * (n1 + n2);
        expected.push_back(a), expected.push_back(star[i] + std::min(1.4 * d, miter_distance) * bisector), expected.push_back(b);
      } else {
        const double from = std::atan2(n1.y, n1.x) * 180.0 / std::numbers::pi;
        const double sweep = std::atan2(cross(n1, n2), dot(n1, n2)) * 180.0 / std::numbers::pi;
        const int steps = static_cast<int>(std::ceil(std::fabs(sweep) / 15.0 - 1e-9));
        for (int k = 0; k <= steps; ++k) expected.push_back(polar(star[i], d, from + sweep * k / steps));
      }
    }
    const auto rings = shrink(star, d, join);
    ASSERT_EQ(rings.size(), 1u) << name_of(join);
    EXPECT_TRUE(same_ring(rings[0], expected, tolerance)) << name_of(join);
  }
}

TEST(Shrink, DumbbellSplitsIntoTwoIslandsAtItsNeck) {
  const Ring seed = test::dumbbell(50.0, 20.0, 10.0);
  for (Join join : {Join::extended, Join::straight, Join::arc, Join::clipped}) {
    const auto rings = shrink(seed, 8.0, join);  // the neck (10 m wide) vanishes
    ASSERT_EQ(rings.size(), 2u) << name_of(join);
    for (const Ring& r : rings) EXPECT_GT(signed_area(r), 0.0);
  }
}

TEST(Shrink, NothingIsLeftWhenTheOffsetExceedsTheInradius) {
  EXPECT_TRUE(shrink(test::square(10), 5.5, Join::clipped).empty());
}

TEST(Shrink, ExpansionHasNoHoleAtReflexCorners) {
  // Outward, the overlapping offsets at a reflex corner must not punch a hole.
  const Ring l_shape{{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}};
  const auto rings = shrink(l_shape, 1.0, Join::extended, 1.4, true);
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_TRUE(same_ring(rings[0], {{-1, -1}, {7, -1}, {7, 4}, {4, 4}, {4, 7}, {-1, 7}}, tolerance));
}

TEST(Preclean, DropsShortSegmentsAndSpikes) {
  // A square with a 1 cm segment and a needle-thin spike.
  const Ring ring{{0, 0}, {5, 0}, {5.01, 0}, {10, 0}, {10, 10}, {5, 10}, {5.05, 30}, {4.95, 10}, {0, 10}};
  const Ring clean = preclean(ring, {0.1, 5.0});
  for (std::size_t i = 0; i < clean.size(); ++i) EXPECT_GT(distance(clean[i], clean[(i + 1) % clean.size()]), 0.1);
  for (const Point& p : clean) EXPECT_LT(p.y, 10.5) << "the spike survived";
  EXPECT_GE(clean.size(), 4u);
}

TEST(Preclean, KeepsAtLeastThreeVertices) {
  const Ring thin{{0, 0}, {10, 0}, {10, 0.01}};
  EXPECT_GE(preclean(thin, {0.0, 30.0}).size(), 3u);
}

}  // namespace
}  // namespace sansui::contour
